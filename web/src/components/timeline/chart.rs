//! The chart's geometry: lanes of step polylines on a virtual-time axis, decimated to at
//! most a few points per pixel column, and "nice" time ticks.

use plc_core::export::value_number;
use plc_core::sim::Trace;
use plc_core::vm::Value;

/// Width of the drawing in SVG units.
pub const WIDTH: f64 = 800.0;
/// Left margin for the lane labels.
pub const LEFT: f64 = 90.0;
/// Height of a digital lane.
pub const DIGITAL_H: f64 = 28.0;
/// Height of an analog lane.
pub const ANALOG_H: f64 = 70.0;
/// Height of the time axis.
pub const AXIS_H: f64 = 22.0;

/// One drawn lane.
#[derive(Debug, Clone, PartialEq)]
pub struct Lane {
    /// The variable path.
    pub path: String,
    /// BOOL lane.
    pub digital: bool,
    /// Top of the lane.
    pub top: f64,
    /// Height of the lane.
    pub height: f64,
    /// The polyline's `points` attribute.
    pub points: String,
    /// The value range of an analog lane (min, max).
    pub range: (f64, f64),
}

/// The chart for a window of virtual time.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chart {
    /// The lanes.
    pub lanes: Vec<Lane>,
    /// Total height.
    pub height: f64,
    /// The window's start and end (ns).
    pub window: (i64, i64),
    /// Time ticks: (x, label).
    pub ticks: Vec<(f64, String)>,
}

/// The x of time `t` in the window.
pub fn x_of(t: i64, window: (i64, i64)) -> f64 {
    let span = (window.1 - window.0).max(1) as f64;
    LEFT + (t - window.0) as f64 / span * (WIDTH - LEFT)
}

/// The time at x in the window.
pub fn t_of(x: f64, window: (i64, i64)) -> i64 {
    let span = (window.1 - window.0).max(1) as f64;
    window.0 + ((x - LEFT) / (WIDTH - LEFT) * span) as i64
}

/// Builds the chart of `trace` for `window`.
pub fn build(trace: &Trace, window: (i64, i64)) -> Chart {
    let paths: Vec<String> = trace.paths().map(str::to_string).collect();
    let mut lanes = Vec::new();
    let mut top = 4.0;
    let first: Option<&Vec<Value>> = trace.samples().next().map(|s| &s.values);
    for (i, path) in paths.into_iter().enumerate() {
        let digital = matches!(first.and_then(|v| v.get(i)), Some(Value::Bool(_)) | None);
        let height = if digital { DIGITAL_H } else { ANALOG_H };
        // The samples in the window, plus the one before it (the value at its start).
        let mut pts: Vec<(i64, f64)> = Vec::new();
        let mut before: Option<(i64, f64)> = None;
        for s in trace.samples() {
            let Some(v) = s.values.get(i).and_then(value_number) else { continue };
            if s.time_ns < window.0 {
                before = Some((s.time_ns, v));
            } else if s.time_ns <= window.1 {
                pts.push((s.time_ns, v));
            }
        }
        if let Some((_, v)) = before {
            pts.insert(0, (window.0, v));
        }
        let range = if digital {
            (0.0, 1.0)
        } else {
            let lo = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
            let hi = pts.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
            if !lo.is_finite() || !hi.is_finite() {
                (0.0, 1.0)
            } else if hi - lo < 1e-12 {
                (lo - 1.0, hi + 1.0)
            } else {
                (lo, hi)
            }
        };
        let pad = if digital { 5.0 } else { 8.0 };
        let y = |v: f64| {
            let f = if digital {
                if v != 0.0 {
                    1.0
                } else {
                    0.0
                }
            } else {
                (v - range.0) / (range.1 - range.0)
            };
            top + height - pad - f * (height - 2.0 * pad)
        };
        let points = polyline(&pts, window, y);
        lanes.push(Lane { path, digital, top, height, points, range });
        top += height + 4.0;
    }
    let height = top + AXIS_H;
    Chart { lanes, height, window, ticks: ticks(window) }
}

/// A step polyline, at most four points per pixel column (first, min, max, last).
fn polyline(pts: &[(i64, f64)], window: (i64, i64), y: impl Fn(f64) -> f64) -> String {
    use std::fmt::Write;
    let mut out = String::new();
    let mut col: Option<(i64, f64, f64, f64, f64)> = None; // (px, first, min, max, last)
    let flush = |out: &mut String, c: (i64, f64, f64, f64, f64), prev_last: Option<f64>| {
        let x = c.0 as f64;
        if let Some(p) = prev_last {
            let _ = write!(out, "{x:.1},{:.1} ", y(p));
        }
        for v in [c.1, c.2, c.3, c.4] {
            let _ = write!(out, "{x:.1},{:.1} ", y(v));
        }
    };
    let mut prev_last = None;
    for &(t, v) in pts {
        let px = x_of(t, window).round() as i64;
        match &mut col {
            Some(c) if c.0 == px => {
                c.2 = c.2.min(v);
                c.3 = c.3.max(v);
                c.4 = v;
            }
            _ => {
                if let Some(c) = col.take() {
                    flush(&mut out, c, prev_last);
                    prev_last = Some(c.4);
                }
                col = Some((px, v, v, v, v));
            }
        }
    }
    if let Some(c) = col {
        // The line ends at the last sample: nothing is drawn past the present.
        flush(&mut out, c, prev_last);
    }
    out
}

/// Ticks at a "nice" step (1, 2, 5 × 10^k ms) with about eight per window.
pub fn ticks(window: (i64, i64)) -> Vec<(f64, String)> {
    let span = (window.1 - window.0).max(1) as f64;
    let raw = span / 8.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step =
        [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * mag).find(|s| *s >= raw).unwrap_or(mag * 10.0);
    let step = step.max(1.0) as i64;
    let mut out = Vec::new();
    let mut t = (window.0.div_euclid(step) + 1) * step;
    if window.0 % step == 0 {
        t = window.0;
    }
    while t <= window.1 && out.len() < 40 {
        out.push((x_of(t, window), time_label(t, step)));
        t += step;
    }
    out
}

/// A time label in ms or s, with as many decimals as the step needs.
pub fn time_label(t: i64, step: i64) -> String {
    if step >= 1_000_000_000 || t.abs() >= 10_000_000_000 {
        let decimals = if step % 1_000_000_000 == 0 {
            0
        } else if step % 100_000_000 == 0 {
            1
        } else {
            3
        };
        format!("{:.*} s", decimals, t as f64 / 1e9)
    } else if step >= 1_000_000 {
        let decimals = if step % 1_000_000 == 0 { 0 } else { 3 };
        format!("{:.*} ms", decimals, t as f64 / 1e6)
    } else {
        format!("{:.3} ms", t as f64 / 1e6)
    }
}

/// The value of lane `i` at time `t` (the last sample at or before it).
pub fn value_at(trace: &Trace, i: usize, t: i64) -> Option<Value> {
    let mut found = None;
    for s in trace.samples() {
        if s.time_ns > t {
            break;
        }
        found = s.values.get(i);
    }
    found.cloned()
}
