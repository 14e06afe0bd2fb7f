//! PNML import: a P/T net (ours or another tool's) as a Petri net POU.

use std::collections::HashMap;

use super::tree::{parse, Element};
use super::{PnmlError, TOOL};
use crate::diagnostics::{LineIndex, Phrase, Said};
use crate::petri::model::{
    Arc, Emergency, GenerationOptions, MacroPlace, Net, PetriPou, Place, Position, Process,
    SyncStyle, Transition,
};
use crate::{msg, phrase};

struct Reader<'a> {
    index: LineIndex<'a>,
}

impl Reader<'_> {
    fn err(&self, e: &Element, said: Said) -> PnmlError {
        PnmlError::at(&self.index, e.offset, said)
    }

    fn id(&self, e: &Element) -> Result<String, PnmlError> {
        match e.attr("id").map(str::trim) {
            Some(id) if !id.is_empty() => Ok(id.to_string()),
            _ => Err(self.err(e, msg!(PnmlNoAttribute, element = e.name, attribute = "id"))),
        }
    }

    fn number<T: std::str::FromStr>(
        &self,
        e: &Element,
        text: &str,
        what: Phrase,
    ) -> Result<T, PnmlError> {
        let text = text.trim();
        text.parse().map_err(|_| self.err(e, msg!(PnmlNotWholeNumber, what = what, text = text)))
    }

    fn position(&self, e: &Element) -> Result<Option<Position>, PnmlError> {
        let Some(pos) = e.child("graphics").and_then(|g| g.child("position")) else {
            return Ok(None);
        };
        let coord = |name: &str| -> Result<f64, PnmlError> {
            let v = pos.attr(name).unwrap_or("0");
            v.trim()
                .parse()
                .map_err(|_| self.err(pos, msg!(PnmlPositionNotNumber, axis = name, value = v)))
        };
        Ok(Some(Position { x: coord("x")?, y: coord("y")? }))
    }
}

/// Our `<toolspecific>` child, if any.
fn ours(e: &Element) -> Option<&Element> {
    e.children_named("toolspecific").find(|t| t.attr("tool") == Some(TOOL))
}

fn text_of(e: Option<&Element>, name: &str) -> String {
    e.and_then(|t| t.child(name)).map(|c| c.text.clone()).unwrap_or_default()
}

/// Collects places, transitions, arcs and references from a page and its sub-pages.
#[derive(Default)]
struct Collected<'e> {
    places: Vec<&'e Element>,
    transitions: Vec<&'e Element>,
    arcs: Vec<&'e Element>,
    /// Reference node id → referenced id.
    refs: Vec<(&'e Element, String)>,
}

fn collect<'e>(
    r: &Reader<'_>,
    page: &'e Element,
    out: &mut Collected<'e>,
) -> Result<(), PnmlError> {
    for c in &page.children {
        match c.name.as_str() {
            "place" => out.places.push(c),
            "transition" => out.transitions.push(c),
            "arc" => out.arcs.push(c),
            "page" => collect(r, c, out)?,
            "referencePlace" | "referenceTransition" => {
                let target = c.attr("ref").ok_or_else(|| {
                    r.err(c, msg!(PnmlNoAttribute, element = c.name, attribute = "ref"))
                })?;
                out.refs.push((c, target.to_string()));
            }
            _ => {}
        }
    }
    Ok(())
}

/// An identifier made from a net's name or id (for the PROGRAM name).
fn identifier(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c);
        } else if !out.ends_with('_') && !out.is_empty() {
            out.push('_');
        }
    }
    let out = out.trim_end_matches('_').to_string();
    match out.chars().next() {
        None => "Net".to_string(),
        Some(c) if c.is_ascii_digit() => format!("Net_{out}"),
        Some(_) => out,
    }
}

/// The number ending a name (`P20` → 20).
fn trailing_number(s: &str) -> Option<i64> {
    let digits: String = s.chars().rev().take_while(char::is_ascii_digit).collect();
    if digits.is_empty() || digits.len() > 5 {
        return None;
    }
    digits.chars().rev().collect::<String>().parse().ok()
}

/// Reads a PNML document holding a P/T net. Only the first net is read.
pub fn import(text: &str) -> Result<PetriPou, PnmlError> {
    let r = Reader { index: LineIndex::new(text) };
    let root = parse(text)?;
    if root.name != "pnml" {
        return Err(r.err(&root, msg!(PnmlNotPnml, element = root.name)));
    }
    let net_el = root.child("net").ok_or_else(|| r.err(&root, msg!(PnmlNoNet, element = "net")))?;
    if let Some(ty) = net_el.attr("type") {
        if !ty.trim_end_matches('#').to_ascii_lowercase().ends_with("ptnet") {
            return Err(r.err(net_el, msg!(PnmlNotPtnet, kind = ty)));
        }
    }
    let mut found = Collected::default();
    collect(&r, net_el, &mut found)?;
    let refs: HashMap<String, String> = found
        .refs
        .iter()
        .map(|(e, t)| (e.attr("id").unwrap_or("").to_string(), t.clone()))
        .collect();
    let resolve = |id: &str| -> String {
        let mut id = id.to_string();
        for _ in 0..=refs.len() {
            match refs.get(&id) {
                Some(t) => id = t.clone(),
                None => break,
            }
        }
        id
    };
    let mut net = Net::default();
    for e in &found.places {
        let tool = ours(e);
        let tokens = match e.annotation("initialMarking") {
            Some(t) => r.number(e, t, phrase!(PnmlWhatInitialMarking))?,
            None => 0,
        };
        let label_text = text_of(tool, "label");
        let label = if label_text.trim().is_empty() {
            i64::MIN
        } else {
            r.number(e, &label_text, phrase!(PnmlWhatCaseLabel))?
        };
        net.places.push(Place {
            id: r.id(e)?,
            name: e.annotation("name").unwrap_or("").trim().to_string(),
            label,
            tokens,
            capacity: match text_of(tool, "capacity") {
                t if t.trim().is_empty() => None,
                t => Some(r.number(e, &t, phrase!(PnmlWhatCapacity))?),
            },
            actions: text_of(tool, "actions"),
            position: r.position(e)?,
            comment: text_of(tool, "comment"),
        });
    }
    default_labels(&mut net.places);
    for e in &found.transitions {
        let tool = ours(e);
        let priority_text = text_of(tool, "priority");
        let priority = if priority_text.trim().is_empty() {
            0
        } else {
            r.number(e, &priority_text, phrase!(PnmlWhatPriority))?
        };
        net.transitions.push(Transition {
            id: r.id(e)?,
            name: e.annotation("name").unwrap_or("").trim().to_string(),
            guard: text_of(tool, "guard"),
            priority,
            position: r.position(e)?,
            comment: text_of(tool, "comment"),
        });
    }
    for e in &found.arcs {
        let end = |name: &str| -> Result<String, PnmlError> {
            e.attr(name).map(resolve).ok_or_else(|| r.err(e, msg!(PnmlArcNoEnd, end = name)))
        };
        let weight = match e.annotation("inscription") {
            Some(t) => r.number(e, t, phrase!(PnmlWhatArcInscription))?,
            None => 1,
        };
        if weight == 0 {
            return Err(r.err(e, msg!(PnmlArcWeightZero)));
        }
        let (from, to) = (end("source")?, end("target")?);
        let known = |id: &str| net.place(id).is_some() || net.transition(id).is_some();
        for id in [&from, &to] {
            if !known(id) {
                return Err(r.err(e, msg!(PnmlArcUnknownNode, id = id)));
            }
        }
        net.arcs.push(Arc { from, to, weight });
    }
    let tool = ours(net_el);
    let mut options = GenerationOptions::default();
    if let Some(o) = tool.and_then(|t| t.child("options")) {
        options.retain = o.attr("retain") == Some("true");
        options.sync = match o.attr("sync") {
            Some("flags") => SyncStyle::Flags,
            Some("stepVariables") | None => SyncStyle::StepVariables,
            Some(other) => return Err(r.err(o, msg!(PnmlUnknownSync, style = other))),
        };
    }
    if let Some(t) = tool {
        for m in t.children_named("macroPlace") {
            net.macro_places.push(MacroPlace {
                id: r.id(m)?,
                name: m.annotation("name").unwrap_or("").trim().to_string(),
                places: refs_of(&r, m)?,
                position: r.position(m)?,
                comment: text_of(Some(m), "comment"),
            });
        }
        for p in t.children_named("process") {
            net.processes.push(Process {
                name: p.attr("name").unwrap_or("").to_string(),
                step_variable: p.attr("stepVariable").unwrap_or("").to_string(),
                places: refs_of(&r, p)?,
            });
        }
        if let Some(e) = t.child("emergency") {
            net.emergency = Some(Emergency {
                place: e
                    .attr("place")
                    .ok_or_else(|| {
                        r.err(e, msg!(PnmlNoAttribute, element = "emergency", attribute = "place"))
                    })?
                    .to_string(),
                condition: text_of(Some(e), "condition"),
            });
        }
    }
    let title = net_el
        .annotation("name")
        .map(str::trim)
        .filter(|n| !n.is_empty())
        .unwrap_or(net_el.attr("id").unwrap_or("Net"));
    Ok(PetriPou {
        name: identifier(title),
        declarations: text_of(tool, "declarations"),
        prologue: text_of(tool, "prologue"),
        epilogue: text_of(tool, "epilogue"),
        net,
        options,
    })
}

fn refs_of(r: &Reader<'_>, e: &Element) -> Result<Vec<String>, PnmlError> {
    e.children_named("place")
        .map(|p| {
            p.attr("ref").map(str::to_string).ok_or_else(|| {
                r.err(p, msg!(PnmlInnerNoAttribute, element = "place", attribute = "ref"))
            })
        })
        .collect()
}

/// Places without a label (`i64::MIN`) get the number ending their name or id when those
/// are all different, else their position 1, 2, 3….
fn default_labels(places: &mut [Place]) {
    let missing: Vec<usize> = (0..places.len()).filter(|&i| places[i].label == i64::MIN).collect();
    if missing.is_empty() {
        return;
    }
    let numbers: Vec<Option<i64>> = missing
        .iter()
        .map(|&i| trailing_number(&places[i].name).or_else(|| trailing_number(&places[i].id)))
        .collect();
    let mut all: Vec<i64> = places.iter().map(|p| p.label).filter(|&l| l != i64::MIN).collect();
    all.extend(numbers.iter().flatten());
    let distinct = {
        let mut s = all.clone();
        crate::order::sort(&mut s);
        s.dedup();
        s.len() == all.len()
    };
    let use_numbers = numbers.iter().all(Option::is_some) && distinct;
    for (k, &i) in missing.iter().enumerate() {
        places[i].label = match numbers[k] {
            Some(n) if use_numbers => n,
            _ => i as i64 + 1,
        };
    }
}
