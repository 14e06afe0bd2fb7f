//! The outline of the textual SFC charts of an ST text, as the web app draws them: steps
//! (with their action associations as written), transitions (the steps they leave and
//! activate, their condition as written) and a top-down layered layout. Names that do not
//! resolve are left out here; the checker reports them.

use crate::syntax::ast::sfc::{SfcElement, SfcStep, SfcTransition};
use crate::syntax::{self, Item};

/// One step of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct OutlineStep {
    /// Its name.
    pub name: String,
    /// `INITIAL_STEP`.
    pub initial: bool,
    /// Its action associations as written (`Visible(N)`, `Fill(L, T#2s)`).
    pub actions: Vec<String>,
}

/// One transition of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct OutlineTransition {
    /// Its name, when it has one.
    pub name: Option<String>,
    /// The steps it leaves (several: an AND convergence).
    pub from: Vec<usize>,
    /// The steps it activates (several: an AND divergence).
    pub to: Vec<usize>,
    /// Its condition as written (`Start AND NOT Stop`, or the statements of a body).
    pub condition: String,
}

/// A chart: the SFC body of one POU.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// The POU's name.
    pub pou: String,
    /// Whether the POU is a PROGRAM (it can run on its own).
    pub program: bool,
    /// The steps, in source order.
    pub steps: Vec<OutlineStep>,
    /// The transitions, in source order.
    pub transitions: Vec<OutlineTransition>,
}

/// Where a chart's steps and transitions are drawn (centres).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ChartLayout {
    /// Per step.
    pub steps: Vec<(f64, f64)>,
    /// Per transition.
    pub transitions: Vec<(f64, f64)>,
}

/// Distance between two layers of steps.
pub const LAYER_DY: f64 = 130.0;
/// Distance between two steps of a layer.
pub const STEP_DX: f64 = 300.0;
/// Distance between the transitions leaving one step.
const BRANCH_DX: f64 = 140.0;
/// Where the first layer and column are.
const ORIGIN: f64 = 70.0;

/// The charts of every POU of `source` written as a textual SFC, in source order.
pub fn outlines(source: &str) -> Vec<Outline> {
    let (file, _) = syntax::parse(source);
    file.items
        .iter()
        .filter_map(|item| match item {
            Item::Pou(p) => {
                let body = p.sfc.as_ref()?;
                Some(outline(
                    source,
                    &p.name.name,
                    p.kind == crate::syntax::ast::PouKind::Program,
                    &body.elements,
                ))
            }
            _ => None,
        })
        .collect()
}

fn text(source: &str, span: crate::diagnostics::Span) -> &str {
    source.get(span.start as usize..span.end as usize).unwrap_or_default()
}

fn outline(source: &str, pou: &str, program: bool, elements: &[SfcElement]) -> Outline {
    let steps: Vec<&SfcStep> = elements
        .iter()
        .filter_map(|e| match e {
            SfcElement::Step(s) => Some(s),
            _ => None,
        })
        .collect();
    let index = |name: &str| steps.iter().position(|s| s.name.name.eq_ignore_ascii_case(name));
    let transitions = elements
        .iter()
        .filter_map(|e| match e {
            SfcElement::Transition(t) => Some(t),
            _ => None,
        })
        .filter_map(|t: &SfcTransition| {
            let from: Vec<usize> = t.from.iter().filter_map(|i| index(&i.name)).collect();
            let to: Vec<usize> = t.to.iter().filter_map(|i| index(&i.name)).collect();
            if from.is_empty() || to.is_empty() {
                return None;
            }
            // The text after the TO list: `:= expr;` or `: statements`, up to END_TRANSITION.
            let rest = source.get(t.header.end as usize..t.span.end as usize).unwrap_or_default();
            let rest = rest.trim();
            let rest = rest
                .strip_suffix("END_TRANSITION")
                .or_else(|| rest.strip_suffix("end_transition"))
                .unwrap_or(rest)
                .trim();
            let rest = rest.strip_prefix(":=").or_else(|| rest.strip_prefix(':')).unwrap_or(rest);
            let condition = rest.trim().trim_end_matches(';').trim();
            Some(OutlineTransition {
                name: t.name.as_ref().map(|n| n.name.clone()),
                from,
                to,
                condition: condition.split_whitespace().collect::<Vec<_>>().join(" "),
            })
        })
        .collect();
    Outline {
        pou: pou.to_string(),
        program,
        steps: steps
            .iter()
            .map(|s| OutlineStep {
                name: s.name.name.clone(),
                initial: s.initial,
                actions: s
                    .associations
                    .iter()
                    .map(|a| text(source, a.span).trim().trim_end_matches(';').trim().to_string())
                    .collect(),
            })
            .collect(),
        transitions,
    }
}

impl Outline {
    /// A top-down layout: steps in layers by their distance from the initial steps (steps
    /// no path reaches go below), in source order across a layer; each transition under
    /// the first step it leaves, the transitions leaving one step side by side.
    pub fn layout(&self) -> ChartLayout {
        let n = self.steps.len();
        let mut depth: Vec<Option<usize>> = vec![None; n];
        let mut queue: std::collections::VecDeque<usize> = std::collections::VecDeque::new();
        for (i, s) in self.steps.iter().enumerate() {
            if s.initial {
                depth[i] = Some(0);
                queue.push_back(i);
            }
        }
        while let Some(s) = queue.pop_front() {
            let d = depth[s].unwrap_or(0);
            for t in self.transitions.iter().filter(|t| t.from.contains(&s)) {
                for &next in &t.to {
                    if depth[next].is_none() {
                        depth[next] = Some(d + 1);
                        queue.push_back(next);
                    }
                }
            }
        }
        let mut deepest = depth.iter().flatten().max().copied().unwrap_or(0);
        for d in depth.iter_mut().filter(|d| d.is_none()) {
            deepest += 1;
            *d = Some(deepest);
        }
        let mut across = vec![0usize; deepest + 2];
        let steps: Vec<(f64, f64)> = depth
            .iter()
            .map(|d| {
                let d = d.unwrap_or(0);
                let k = across[d];
                across[d] += 1;
                (ORIGIN + k as f64 * STEP_DX, ORIGIN + d as f64 * LAYER_DY)
            })
            .collect();
        let mut leaving = vec![0usize; n];
        let counts: Vec<usize> = (0..n)
            .map(|s| self.transitions.iter().filter(|t| t.from.first() == Some(&s)).count())
            .collect();
        let transitions = self
            .transitions
            .iter()
            .map(|t| {
                let s = t.from[0];
                let k = leaving[s];
                leaving[s] += 1;
                let spread = (k as f64 - (counts[s] as f64 - 1.0) / 2.0) * BRANCH_DX;
                let xs: f64 = t.from.iter().map(|&f| steps[f].0).sum::<f64>() / t.from.len() as f64;
                let y = t.from.iter().map(|&f| steps[f].1).fold(f64::MIN, f64::max);
                (xs + spread, y + LAYER_DY / 2.0)
            })
            .collect();
        ChartLayout { steps, transitions }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BLINKER: &str = "PROGRAM Blinker
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Visible : BOOL; END_VAR
INITIAL_STEP S1 : END_STEP
TRANSITION T1 FROM S1 TO S2 := Start; END_TRANSITION
STEP S2 : Visible(N); END_STEP
TRANSITION T2 FROM S2 TO S3 := S2.T >= T#500ms; END_TRANSITION
STEP S3 : END_STEP
TRANSITION FROM S3 TO S2 := S3.T >= T#300ms AND NOT Stop; END_TRANSITION
TRANSITION FROM S3 TO S1 := Stop; END_TRANSITION
END_PROGRAM
FUNCTION_BLOCK NotAChart VAR x : INT; END_VAR x := 1; END_FUNCTION_BLOCK
";

    #[test]
    fn the_blinker_is_outlined_with_its_conditions_and_actions() {
        let charts = outlines(BLINKER);
        assert_eq!(charts.len(), 1, "only SFC bodies are charts");
        let c = &charts[0];
        assert_eq!((c.pou.as_str(), c.program), ("Blinker", true));
        let names: Vec<&str> = c.steps.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["S1", "S2", "S3"]);
        assert!(c.steps[0].initial && !c.steps[1].initial);
        assert_eq!(c.steps[1].actions, ["Visible(N)"]);
        let t: Vec<String> = c
            .transitions
            .iter()
            .map(|t| format!("{:?} {:?}->{:?} {}", t.name, t.from, t.to, t.condition))
            .collect();
        assert_eq!(
            t,
            [
                "Some(\"T1\") [0]->[1] Start",
                "Some(\"T2\") [1]->[2] S2.T >= T#500ms",
                "None [2]->[1] S3.T >= T#300ms AND NOT Stop",
                "None [2]->[0] Stop",
            ]
        );
    }

    #[test]
    fn layers_go_down_from_the_initial_step_and_branches_spread() {
        let lay = outlines(BLINKER)[0].layout();
        assert_eq!(lay.steps, [(70.0, 70.0), (70.0, 200.0), (70.0, 330.0)]);
        assert_eq!(lay.transitions[0], (70.0, 135.0));
        // The two transitions leaving S3 sit side by side under it.
        assert_eq!(lay.transitions[2], (0.0, 395.0));
        assert_eq!(lay.transitions[3], (140.0, 395.0));
    }
}
