//! Random input histories for a random scenario, and shrinking a failing one.
//!
//! The generator is SplitMix64 (a fixed, portable sequence for a seed): the same seed gives
//! the same events natively and in wasm32. A BOOL input given `pulse = [MIN, MAX]` is
//! pressed for a random time in that range, released for another, and so on; a number given
//! `walk = [LOW, HIGH]` moves by a random step of at most `step` every `every`. Shrinking
//! drops events one at a time while the run still fails, so the list printed is one no
//! event of which can be left out.

use super::format::{parse_duration, ExerciseError, Restart, Scenario};

/// An input set at a time: (time in ns, input, IEC literal); or a restart, with
/// [`RESTART`] for the input and `warm` or `cold` for the value.
pub type Event = (i64, String, String);

/// The input name of a restart event.
pub const RESTART: &str = "(restart)";

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `lo ..= hi`.
    fn between(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo).max(0) as u64 + 1;
        lo + (self.next() % span) as i64
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The events of one random run of `s` with `seed`, in time order.
pub fn events(s: &Scenario, seed: u64) -> Result<Vec<Event>, ExerciseError> {
    let end = s.duration_ns()?;
    let mut rng = Rng(seed);
    let mut out: Vec<Event> = step_events(s);
    for input in &s.inputs {
        if let Some([a, b]) = &input.pulse {
            let (lo, hi) = (s.time(a, "pulse")?, s.time(b, "pulse")?);
            let mut t = rng.between(0, hi);
            let mut on = true;
            while t < end {
                out.push((t, input.name.clone(), if on { "TRUE" } else { "FALSE" }.into()));
                t += rng.between(lo, hi);
                on = !on;
            }
        } else if let Some([lo, hi]) = input.walk {
            let step = input.step.unwrap_or((hi - lo) / 10.0).abs();
            let every = match &input.every {
                Some(e) => parse_duration(e).map_err(|m| ExerciseError { message: m })?,
                None => 100_000_000,
            }
            .max(1);
            let mut v = lo + (hi - lo) * rng.unit();
            let mut t = 0;
            while t < end {
                out.push((t, input.name.clone(), format!("{}", v.round() as i64)));
                v = (v + step * (2.0 * rng.unit() - 1.0)).clamp(lo, hi);
                t += every;
            }
        }
    }
    crate::order::sort_by_key(&mut out, |e| e.0);
    Ok(out)
}

/// The events of a scenario's fixed steps, in time order.
pub fn step_events(s: &Scenario) -> Vec<Event> {
    let mut out = Vec::new();
    for step in &s.steps {
        let at = parse_duration(&step.at).unwrap_or(0);
        if let Some(kind) = step.restart {
            let kind = match kind {
                Restart::Warm => "warm",
                Restart::Cold => "cold",
            };
            out.push((at, RESTART.to_string(), kind.to_string()));
        }
        for (name, value) in &step.set {
            out.push((at, name.clone(), value.literal()));
        }
    }
    crate::order::sort_by_key(&mut out, |e| e.0);
    out
}

/// A shortest failing list found by dropping events one at a time while `fails` holds.
pub fn shrink(mut events: Vec<Event>, fails: impl Fn(&[Event]) -> bool) -> Vec<Event> {
    let mut i = 0;
    while i < events.len() {
        let mut fewer = events.clone();
        fewer.remove(i);
        if fails(&fewer) {
            events = fewer;
        } else {
            i += 1;
        }
    }
    events
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_gives_the_same_sequence() {
        let (mut a, mut b) = (Rng(7), Rng(7));
        let xs: Vec<u64> = (0..5).map(|_| a.next()).collect();
        let ys: Vec<u64> = (0..5).map(|_| b.next()).collect();
        assert_eq!(xs, ys);
        // SplitMix64's first output for seed 0 (its reference value).
        assert_eq!(Rng(0).next(), 0xE220_A839_7B1D_CDAF);
    }

    #[test]
    fn shrinking_keeps_only_what_the_failure_needs() {
        let ev = |t: i64, n: &str| (t, n.to_string(), "TRUE".to_string());
        let all = vec![ev(1, "a"), ev(2, "x"), ev(3, "b"), ev(4, "y")];
        let needs_a_and_b =
            |e: &[Event]| e.iter().any(|x| x.1 == "a") && e.iter().any(|x| x.1 == "b");
        assert_eq!(shrink(all, needs_a_and_b), vec![ev(1, "a"), ev(3, "b")]);
    }
}
