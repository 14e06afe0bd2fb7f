//! Unit tests of the Petri net module. Expected values are derived by hand in comments.
#![allow(clippy::unwrap_used)]

mod analysis;
mod codegen;
mod conflicts;
#[cfg(not(target_arch = "wasm32"))]
mod semiflows;

use super::*;

/// A net from `(id, initial tokens)` places and `(id, inputs, outputs)` transitions; an
/// arc end written `p*2` has weight 2. Labels are 1, 2, 3… in place order.
pub(super) fn net(places: &[(&str, u32)], transitions: &[(&str, &[&str], &[&str])]) -> Net {
    let arc = |s: &str| -> (String, u32) {
        match s.split_once('*') {
            Some((p, w)) => (p.to_string(), w.parse().unwrap()),
            None => (s.to_string(), 1),
        }
    };
    let mut n = Net::default();
    for (i, (id, tokens)) in places.iter().enumerate() {
        n.places.push(Place::new(*id, i as i64 + 1, *tokens));
    }
    for (id, ins, outs) in transitions {
        n.transitions.push(Transition::new(*id, ""));
        for s in *ins {
            let (p, weight) = arc(s);
            n.arcs.push(Arc { from: p, to: id.to_string(), weight });
        }
        for s in *outs {
            let (p, weight) = arc(s);
            n.arcs.push(Arc { from: id.to_string(), to: p, weight });
        }
    }
    n
}

/// A POU around a net, with BOOL inputs `g1…gN` declared.
pub(super) fn pou(net: Net, inputs: usize) -> PetriPou {
    let decls: String = (1..=inputs).map(|i| format!("    g{i} : BOOL;\n")).collect();
    PetriPou {
        name: "Net".into(),
        declarations: if inputs > 0 {
            format!("VAR_INPUT\n{decls}END_VAR\n")
        } else {
            String::new()
        },
        prologue: String::new(),
        epilogue: String::new(),
        net,
        options: GenerationOptions::default(),
    }
}

/// Producer P0 -produce-> P1 -put(takes a free slot, adds an item)-> P0; consumer
/// C0 -get(takes an item, frees a slot)-> C1 -consume-> C0; a buffer of two free slots.
pub(super) fn producer_consumer() -> Net {
    net(
        &[("P0", 1), ("P1", 0), ("C0", 1), ("C1", 0), ("items", 0), ("free", 2)],
        &[
            ("produce", &["P0"], &["P1"]),
            ("put", &["P1", "free"], &["P0", "items"]),
            ("get", &["C0", "items"], &["C1", "free"]),
            ("consume", &["C1"], &["C0"]),
        ],
    )
}
