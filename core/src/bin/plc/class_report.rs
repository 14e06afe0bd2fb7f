//! `plc grade … --format html`: the class report, one self-contained page (inline CSS and
//! SVG, no script, nothing fetched, so it opens from disk and prints): a row per
//! submission (the student's name, the score, the first failure with its time), each
//! scenario's pass rate, a histogram of the scores, and the most common first failures
//! with how many students hit them. Made from the grader's reports; nothing is graded
//! twice. Every word it shows is in [`Words`].

use std::collections::BTreeMap;
use std::fmt::Write;

use plc_core::exercise::{time_text, Exercise, Report};

use super::grade::Row;

/// The words of the page, in one place for the translation catalogue to come.
struct Words;

impl Words {
    const TITLE: &'static str = "Class report";
    const SUBMISSIONS: &'static str = "Submissions";
    const NAME: &'static str = "Name";
    const FILE: &'static str = "File";
    const HANDED_IN: &'static str = "Handed in";
    const SCORE: &'static str = "Score";
    const FIRST_FAILURE: &'static str = "First failure";
    const AT: &'static str = "At";
    const PASS_RATES: &'static str = "Pass rate per scenario";
    const SCENARIO: &'static str = "Scenario";
    const WEIGHT: &'static str = "Weight";
    const PASSED: &'static str = "Passed";
    const HISTOGRAM: &'static str = "Scores";
    const COMMON: &'static str = "Most common first failures";
    const STUDENTS: &'static str = "Students";
    const NOT_GRADED: &'static str = "not graded";
    const ALL_PASSED: &'static str = "every scenario passed";
    const NO_FAILURES: &'static str = "No submission failed.";
    const NOTHING_GRADED: &'static str = "No submission could be graded.";
    const EXERCISE: &'static str = "Exercise";
    const SCENARIOS: &'static str = "scenario(s)";
    const POINTS: &'static str = "point(s)";
    const GRADED: &'static str = "graded";
    const FULL: &'static str = "passed every scenario";
    const MEAN: &'static str = "mean score";
    const MEDIAN: &'static str = "median score";
    const PER_SCORE: &'static str = "Submissions per score";
    const SCORE_AXIS: &'static str = "score (points)";
    const OF: &'static str = "of";
}

/// Text for HTML: `&`, `<`, `>` and quotes escaped.
fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A row's first failure: what went wrong first and when (`None` when it passed).
struct First {
    /// The line shown in the row.
    text: String,
    /// Its time, for a failed scenario.
    at: Option<String>,
    /// What groups it with other students' failures: the scenario and the expectation it
    /// missed, or the kind of error (its text before the first `: `, which carries the
    /// place).
    key: String,
}

fn first_failure(report: &Report) -> Option<First> {
    if let Some(e) = &report.error {
        let key = e.split(": ").next().unwrap_or(e).to_string();
        return Some(First { text: e.clone(), at: None, key });
    }
    report.scenarios.iter().find_map(|s| {
        let f = s.failure.as_ref()?;
        Some(First {
            text: format!("“{}”: {}", s.name, f.actual),
            at: Some(time_text(f.time_ns)),
            key: format!("“{}”: expected {}", s.name, f.expected),
        })
    })
}

/// The name a row shows: the student's, or the file's name without its folder.
fn shown_name(row: &Row) -> String {
    row.student.clone().unwrap_or_else(|| {
        std::path::Path::new(&row.name)
            .file_name()
            .map_or(row.name.clone(), |n| n.to_string_lossy().into_owned())
    })
}

const STYLE: &str = "
:root { color-scheme: light; --ink: #1d2430; --muted: #5b6472; --line: #d9dee6; --ok: #1f7a3d;
  --bad: #b42318; --bar: #3566c8; --soft: #f3f5f8; }
* { box-sizing: border-box; }
body { font: 15px/1.45 system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif; color: var(--ink);
  margin: 0 auto; max-width: 1100px; padding: 24px; }
h1 { font-size: 1.5rem; margin: 0 0 4px; }
h2 { font-size: 1.1rem; margin: 28px 0 8px; }
.sub { color: var(--muted); margin: 0 0 16px; }
.summary { display: flex; flex-wrap: wrap; gap: 12px; margin: 0; padding: 0; list-style: none; }
.summary li { background: var(--soft); border: 1px solid var(--line); border-radius: 8px;
  padding: 8px 14px; }
.summary b { display: block; font-size: 1.3rem; font-variant-numeric: tabular-nums; }
table { border-collapse: collapse; width: 100%; }
th, td { text-align: left; vertical-align: top; padding: 6px 8px; border-bottom: 1px solid var(--line); }
th { font-size: .85rem; color: var(--muted); font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.file { color: var(--muted); font-size: .85rem; word-break: break-all; }
td.when { white-space: nowrap; font-variant-numeric: tabular-nums; }
td small { color: var(--muted); }
.full { color: var(--ok); font-weight: 600; }
.zero, .refused { color: var(--bad); }
.rate { display: flex; align-items: center; gap: 8px; min-width: 180px; }
.meter { flex: 1; height: 10px; background: var(--soft); border: 1px solid var(--line); border-radius: 5px;
  overflow: hidden; }
.meter span { display: block; height: 100%; background: var(--bar); }
.grid { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 1fr); gap: 24px; }
@media (max-width: 800px) { .grid { grid-template-columns: 1fr; } }
svg text { font: 12px system-ui, sans-serif; fill: var(--ink); }
@media print { body { padding: 0; } .grid { grid-template-columns: 1fr 1fr; } }
";

/// The class report of `rows` graded against `ex`.
pub(crate) fn html(ex: &Exercise, rows: &[Row]) -> String {
    let total: u32 = ex.scenarios.iter().map(|s| s.weight).sum();
    let graded: Vec<&Report> = rows.iter().filter_map(|r| r.result.as_ref().ok()).collect();
    let refused = rows.len() - graded.len();
    let mut out = String::new();
    let title = format!("{} — {}", Words::TITLE, ex.title);
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n<h1>{}</h1>\n\
         <p class=\"sub\">{} <code>{}</code> · {} {} · {total} {}</p>\n",
        esc(&title),
        esc(&title),
        Words::EXERCISE,
        esc(&ex.id),
        ex.scenarios.len(),
        Words::SCENARIOS,
        Words::POINTS,
    );
    summary(&mut out, &graded, refused, total);
    let _ = write!(out, "<div class=\"grid\">\n<section>\n<h2>{}</h2>\n", Words::HISTOGRAM);
    histogram(&mut out, &graded, total);
    let _ = write!(out, "</section>\n<section>\n<h2>{}</h2>\n", Words::PASS_RATES);
    pass_rates(&mut out, ex, &graded);
    let _ = write!(out, "</section>\n</div>\n<h2>{}</h2>\n", Words::COMMON);
    common_failures(&mut out, &graded);
    let _ = writeln!(out, "<h2>{}</h2>", Words::SUBMISSIONS);
    submissions(&mut out, rows);
    out.push_str("</body>\n</html>\n");
    out
}

fn summary(out: &mut String, graded: &[&Report], refused: usize, total: u32) {
    let n = graded.len();
    let full = graded.iter().filter(|r| r.error.is_none() && r.score == total).count();
    let mean = if n == 0 {
        "—".to_string()
    } else {
        let sum: u32 = graded.iter().map(|r| r.score).sum();
        format!("{:.1} / {total}", f64::from(sum) / n as f64)
    };
    let median = if n == 0 {
        "—".to_string()
    } else {
        let mut scores: Vec<u32> = graded.iter().map(|r| r.score).collect();
        scores.sort_unstable();
        let m = if n % 2 == 1 {
            f64::from(scores[n / 2])
        } else {
            (f64::from(scores[n / 2 - 1]) + f64::from(scores[n / 2])) / 2.0
        };
        format!("{} / {total}", (m * 10.0).round() / 10.0)
    };
    out.push_str("<ul class=\"summary\">\n");
    for (value, label) in [
        (n.to_string(), Words::GRADED),
        (refused.to_string(), Words::NOT_GRADED),
        (full.to_string(), Words::FULL),
        (mean, Words::MEAN),
        (median, Words::MEDIAN),
    ] {
        let _ = writeln!(out, "<li><b>{}</b>{}</li>", esc(&value), esc(label));
    }
    out.push_str("</ul>\n");
}

/// A bar chart of how many submissions got each score (or each tenth of the points when
/// there are more than 20).
fn histogram(out: &mut String, graded: &[&Report], total: u32) {
    if graded.is_empty() {
        let _ = writeln!(out, "<p>{}</p>", Words::NOTHING_GRADED);
        return;
    }
    // (label, lowest score, highest score) per bar.
    let bins: Vec<(String, u32, u32)> = if total <= 20 {
        (0..=total).map(|s| (s.to_string(), s, s)).collect()
    } else {
        let mut bins = Vec::new();
        let mut low = 0;
        for k in 1..=10u32 {
            let high = if k == 10 { total } else { total * k / 10 };
            if high >= low {
                bins.push((format!("{low}–{high}"), low, high));
                low = high + 1;
            }
        }
        bins
    };
    let counts: Vec<usize> = bins
        .iter()
        .map(|(_, lo, hi)| graded.iter().filter(|r| (*lo..=*hi).contains(&r.score)).count())
        .collect();
    let most = counts.iter().copied().max().unwrap_or(0).max(1);
    let (width, height, left, bottom, top) = (480.0, 220.0, 36.0, 34.0, 18.0);
    let plot_h = height - bottom - top;
    let slot = (width - left - 8.0) / bins.len() as f64;
    let described: Vec<String> =
        bins.iter().zip(&counts).map(|((label, _, _), c)| format!("{label}: {c}")).collect();
    let _ = writeln!(
        out,
        "<svg viewBox=\"0 0 {width} {height}\" width=\"100%\" role=\"img\" aria-labelledby=\"hist-title\">\n\
         <title id=\"hist-title\">{}: {}</title>",
        Words::PER_SCORE,
        esc(&described.join(", "))
    );
    let _ = writeln!(
        out,
        "<line x1=\"{left}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#5b6472\"/>",
        height - bottom,
        width - 8.0,
        height - bottom
    );
    for (i, ((label, _, _), count)) in bins.iter().zip(&counts).enumerate() {
        let x = left + slot * i as f64;
        let h = plot_h * *count as f64 / most as f64;
        let y = height - bottom - h;
        let bar_w = (slot * 0.7).max(2.0);
        let cx = x + slot / 2.0;
        let _ = writeln!(
            out,
            "<rect x=\"{:.1}\" y=\"{y:.1}\" width=\"{bar_w:.1}\" height=\"{h:.1}\" fill=\"#3566c8\" rx=\"2\"><title>{}: {count}</title></rect>",
            cx - bar_w / 2.0,
            esc(label)
        );
        if *count > 0 {
            let _ = writeln!(
                out,
                "<text x=\"{cx:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{count}</text>",
                y - 4.0
            );
        }
        let _ = writeln!(
            out,
            "<text x=\"{cx:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
            height - bottom + 16.0,
            esc(label)
        );
    }
    let _ = writeln!(
        out,
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" fill=\"#5b6472\">{}</text>\n</svg>",
        left + (width - left) / 2.0,
        height - 2.0,
        Words::SCORE_AXIS
    );
}

fn pass_rates(out: &mut String, ex: &Exercise, graded: &[&Report]) {
    let n = graded.len();
    let _ = writeln!(
        out,
        "<table>\n<thead><tr><th>{}</th><th class=\"num\">{}</th><th>{}</th></tr></thead>\n<tbody>",
        Words::SCENARIO,
        Words::WEIGHT,
        Words::PASSED
    );
    for s in &ex.scenarios {
        let passed = graded
            .iter()
            .filter(|r| r.error.is_none())
            .filter(|r| r.scenarios.iter().any(|x| x.name == s.name && x.passed()))
            .count();
        let percent = if n == 0 { 0.0 } else { (100.0 * passed as f64 / n as f64).round() };
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td class=\"num\">{}</td><td><div class=\"rate\"><div class=\"meter\"><span style=\"width:{percent:.0}%\"></span></div><span class=\"num\">{passed} / {n} ({percent:.0} %)</span></div></td></tr>",
            esc(&s.name),
            s.weight
        );
    }
    out.push_str("</tbody>\n</table>\n");
}

fn common_failures(out: &mut String, graded: &[&Report]) {
    // The kind of failure → how many students' first failure it was.
    let mut groups: BTreeMap<String, usize> = BTreeMap::new();
    for r in graded {
        if let Some(f) = first_failure(r) {
            *groups.entry(f.key).or_default() += 1;
        }
    }
    if groups.is_empty() {
        let text = if graded.is_empty() { Words::NOTHING_GRADED } else { Words::NO_FAILURES };
        let _ = writeln!(out, "<p>{text}</p>");
        return;
    }
    let mut sorted: Vec<(String, usize)> = groups.into_iter().collect();
    sorted.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    let n = graded.len();
    let _ = writeln!(
        out,
        "<table>\n<thead><tr><th>{}</th><th>{}</th></tr></thead>\n<tbody>",
        Words::FIRST_FAILURE,
        Words::STUDENTS
    );
    for (key, count) in sorted.iter().take(10) {
        let percent = (100.0 * *count as f64 / n as f64).round();
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td><div class=\"rate\"><div class=\"meter\"><span style=\"width:{percent:.0}%\"></span></div><span class=\"num\">{count} {} {n}</span></div></td></tr>",
            esc(key),
            Words::OF
        );
    }
    out.push_str("</tbody>\n</table>\n");
}

/// A failure as a cell: what went wrong, and the details a random run adds (after ` — `:
/// the seed, the replay, the shortest failing events) in smaller type.
fn failure_html(text: &str) -> String {
    match text.split_once(" — ") {
        Some((what, details)) => format!("{}<br><small>{}</small>", esc(what), esc(details)),
        None => esc(text),
    }
}

/// An ISO 8601 time as people read it: `2025-03-04T10:15:00.000Z` → `2025-03-04 10:15 UTC`
/// (other texts as they are).
fn when_text(iso: &str) -> String {
    let b = iso.as_bytes();
    let iso_like = b.len() >= 16
        && b[4] == b'-'
        && b[7] == b'-'
        && b[10] == b'T'
        && b[13] == b':'
        && iso.is_char_boundary(16);
    if !iso_like {
        return iso.to_string();
    }
    let zone = if iso.ends_with('Z') { " UTC" } else { "" };
    format!("{} {}{zone}", &iso[..10], &iso[11..16])
}

fn submissions(out: &mut String, rows: &[Row]) {
    let handed = rows.iter().any(|r| r.handed_in.is_some());
    let _ = write!(
        out,
        "<table>\n<thead><tr><th>{}</th><th class=\"num\">{}</th><th>{}</th><th class=\"num\">{}</th>",
        Words::NAME,
        Words::SCORE,
        Words::FIRST_FAILURE,
        Words::AT
    );
    if handed {
        let _ = write!(out, "<th>{}</th>", Words::HANDED_IN);
    }
    let _ = writeln!(out, "<th>{}</th></tr></thead>\n<tbody>", Words::FILE);
    for row in rows {
        let (score, failure, at) = match &row.result {
            Err(e) => {
                // The file is in its own column.
                let prefix = format!("plc: {}: ", row.name);
                (
                    format!("<span class=\"refused\">{}</span>", Words::NOT_GRADED),
                    esc(e.strip_prefix(&prefix).unwrap_or(e)),
                    String::new(),
                )
            }
            Ok(r) => {
                let class = if r.error.is_none() && r.score == r.total {
                    "full"
                } else if r.score == 0 {
                    "zero"
                } else {
                    "part"
                };
                let score = format!("<span class=\"{class}\">{} / {}</span>", r.score, r.total);
                match first_failure(r) {
                    Some(f) => {
                        (score, failure_html(&f.text), f.at.map(|a| esc(&a)).unwrap_or_default())
                    }
                    None => (
                        score,
                        format!("<span class=\"full\">{}</span>", Words::ALL_PASSED),
                        String::new(),
                    ),
                }
            }
        };
        let _ = write!(
            out,
            "<tr><td>{}</td><td class=\"num\">{score}</td><td>{failure}</td><td class=\"num\">{at}</td>",
            esc(&shown_name(row))
        );
        if handed {
            let when = row.handed_in.as_deref().map(when_text).unwrap_or_default();
            let _ = write!(out, "<td class=\"when\">{}</td>", esc(&when));
        }
        let file = std::path::Path::new(&row.name)
            .file_name()
            .map_or(row.name.clone(), |n| n.to_string_lossy().into_owned());
        let _ = writeln!(
            out,
            "<td class=\"file\" title=\"{}\">{}</td></tr>",
            esc(&row.name),
            esc(&file)
        );
    }
    out.push_str("</tbody>\n</table>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_and_failures_read_as_people_read_them() {
        assert_eq!(when_text("2025-03-04T10:15:00.000Z"), "2025-03-04 10:15 UTC");
        assert_eq!(when_text("2025-03-04T10:15:00+01:00"), "2025-03-04 10:15");
        assert_eq!(when_text("yesterday"), "yesterday");
        assert_eq!(when_text("2025-03-04Tü"), "2025-03-04Tü");
        assert_eq!(
            failure_html("A was TRUE — random run with seed 7 <x>"),
            "A was TRUE<br><small>random run with seed 7 &lt;x&gt;</small>"
        );
        assert_eq!(esc("\"a\" & 'b'"), "&quot;a&quot; &amp; &#39;b&#39;");
    }
}
