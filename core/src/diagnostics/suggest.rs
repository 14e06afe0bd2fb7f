//! `did you mean NAME?`: the declared name an unknown one is most probably a misspelling
//! of. Names compare as IEC 61131-3 compares them (case-insensitively), by the optimal
//! string alignment distance (Damerau–Levenshtein with adjacent transpositions: `Motr`,
//! `Mtoor` and `Mootor` are each one edit from `Motor`).
//!
//! The rule, chosen so that a hint is rarely noise:
//! - names of one or two characters get no hint (`x` is one edit from every other
//!   one-letter name);
//! - names of three or four characters get a hint only at distance 1;
//! - longer names get one at distance 1 or 2;
//! - a candidate must be at most that many characters longer or shorter, and no hint is
//!   given at all when the name is the candidate spelled the same way;
//! - among the candidates at the smallest distance, the first one given wins (callers list
//!   them in declaration order), so the hint is deterministic.

/// The largest distance at which `name` (as written) gets a hint: 0 means none.
pub fn max_distance(name: &str) -> usize {
    match name.chars().count() {
        0..=2 => 0,
        3..=4 => 1,
        _ => 2,
    }
}

/// The optimal string alignment distance between `a` and `b`, ignoring ASCII case; stops
/// early (returning `limit + 1`) once the distance is certainly above `limit`.
pub fn distance(a: &str, b: &str, limit: usize) -> usize {
    let a: Vec<char> = a.chars().map(|c| c.to_ascii_uppercase()).collect();
    let b: Vec<char> = b.chars().map(|c| c.to_ascii_uppercase()).collect();
    if a.len().abs_diff(b.len()) > limit {
        return limit + 1;
    }
    // Three rows of the dynamic programme: two back (transpositions), one back, this one.
    let width = b.len() + 1;
    let mut before: Vec<usize> = vec![0; width];
    let mut prev: Vec<usize> = (0..width).collect();
    let mut row: Vec<usize> = vec![0; width];
    for i in 1..=a.len() {
        row[0] = i;
        let mut best = row[0];
        for j in 1..width {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut d = (prev[j] + 1).min(row[j - 1] + 1).min(prev[j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d = d.min(before[j - 2] + 1);
            }
            row[j] = d;
            best = best.min(d);
        }
        if best > limit {
            return limit + 1;
        }
        std::mem::swap(&mut before, &mut prev);
        std::mem::swap(&mut prev, &mut row);
    }
    prev[b.len()]
}

/// The candidate `name` is most probably a misspelling of (see the module comment), as the
/// candidate spells it. Candidates are taken in the order given; repeats and names no
/// user writes (holding `__`, as generated variables do) are passed over.
pub fn closest<'c, I>(name: &str, candidates: I) -> Option<&'c str>
where
    I: IntoIterator<Item = &'c str>,
{
    let limit = max_distance(name);
    if limit == 0 {
        return None;
    }
    let mut best: Option<(usize, &'c str)> = None;
    for candidate in candidates {
        if candidate.contains("__") || candidate.eq_ignore_ascii_case(name) {
            continue;
        }
        let bound = best.map_or(limit, |(d, _)| d.saturating_sub(1));
        let d = distance(name, candidate, bound);
        if d <= bound && d > 0 {
            best = Some((d, candidate));
            if d == 1 {
                // Nothing closer than one edit remains possible but an equal name,
                // which is passed over.
                break;
            }
        }
    }
    best.map(|(_, c)| c)
}

/// [`closest`] for candidates that come in no particular order (the keys of a map): a tie
/// goes to the name first in alphabetical order (ignoring case), so the hint is still
/// deterministic.
pub fn closest_in_set<'c, I>(name: &str, candidates: I) -> Option<&'c str>
where
    I: IntoIterator<Item = &'c str>,
{
    let limit = max_distance(name);
    if limit == 0 {
        return None;
    }
    let mut best: Option<(usize, &'c str)> = None;
    for candidate in candidates {
        if candidate.contains("__") || candidate.eq_ignore_ascii_case(name) {
            continue;
        }
        let bound = best.map_or(limit, |(d, _)| d);
        let d = distance(name, candidate, bound);
        let better = match best {
            None => d <= limit,
            Some((b, c)) => {
                d < b || d == b && candidate.to_ascii_uppercase() < c.to_ascii_uppercase()
            }
        };
        if better && d > 0 {
            best = Some((d, candidate));
        }
    }
    best.map(|(_, c)| c)
}

/// `; did you mean NAME?` for a message, or nothing.
pub fn hint(suggestion: Option<&str>) -> String {
    suggestion.map(|s| format!("; did you mean {s}?")).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_counts_edits_and_transpositions_ignoring_case() {
        assert_eq!(distance("Motr", "Motor", 5), 1);
        assert_eq!(distance("Mtoor", "Motor", 5), 1, "a transposition is one edit");
        assert_eq!(distance("MOTOR", "motor", 5), 0);
        assert_eq!(distance("Motro", "Motor", 5), 1);
        assert_eq!(distance("Mtr", "Motor", 5), 2);
        assert_eq!(distance("abc", "xyz", 5), 3);
        assert_eq!(distance("", "abc", 5), 3);
        assert_eq!(distance("Lamp", "Lamp2", 5), 1);
        assert_eq!(distance("Start", "Stop", 1), 2, "stopped early above the limit");
    }

    #[test]
    fn the_closest_declared_name_wins_then_the_first_declared() {
        let names = ["Start", "Stop", "Motor"];
        assert_eq!(closest("Motr", names), Some("Motor"));
        assert_eq!(closest("motr", names), Some("Motor"), "spelled as declared");
        assert_eq!(closest("Stp", names), Some("Stop"));
        assert_eq!(closest("Strat", names), Some("Start"));
        // Two at distance 1: the one declared first.
        assert_eq!(closest("Lamp", ["Lamp1", "Lamp2"]), Some("Lamp1"));
        assert_eq!(closest("Lamp", ["Lamp2", "Lamp1"]), Some("Lamp2"));
        // A closer one later beats a farther one first.
        assert_eq!(closest("Pumps", ["Pump_1", "Pumpz"]), Some("Pumpz"));
    }

    #[test]
    fn in_a_set_a_tie_goes_to_the_first_name_in_alphabetical_order() {
        assert_eq!(closest_in_set("Lamp", ["lamp2", "Lamp1", "Lump"]), Some("Lamp1"));
        assert_eq!(closest_in_set("Lamp", ["Lump", "Lamp2"]), Some("Lamp2"));
        assert_eq!(closest_in_set("Motr", ["Mtr", "Motor"]), Some("Motor"));
        assert_eq!(closest_in_set("x", ["y"]), None);
        assert_eq!(closest_in_set("Pump", ["Motor"]), None);
    }

    #[test]
    fn short_names_and_far_names_get_no_hint() {
        assert_eq!(closest("x", ["y", "z"]), None);
        assert_eq!(closest("ab", ["abc"]), None);
        assert_eq!(closest("Mtr", ["Motor"]), None, "four letters or fewer: one edit at most");
        assert_eq!(closest("Pump", ["Motor"]), None);
        assert_eq!(closest("Conveyor", ["Conveyor_Belt_Speed"]), None);
        assert_eq!(closest("Motor", ["MOTOR"]), None, "the same name is no misspelling");
        assert_eq!(closest("LdPow", ["LdPow__1"]), None, "generated names are not offered");
    }

    #[test]
    fn the_hint_reads_as_a_question() {
        assert_eq!(hint(Some("Motor")), "; did you mean Motor?");
        assert_eq!(hint(None), "");
    }
}
