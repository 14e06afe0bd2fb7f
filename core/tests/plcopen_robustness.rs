#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The importer never panics: the LD samples of `tests/samples/` with lines dropped and
//! wires pointed elsewhere either import (and then lower and export without panicking) or
//! give an error.

use plc_core::plcopen::{export, import};
use proptest::prelude::*;

fn samples() -> Vec<String> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/samples");
    let mut names: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    names.sort();
    let texts: Vec<String> = names
        .into_iter()
        .filter(|p| p.file_name().is_some_and(|n| n.to_string_lossy().starts_with("ld_")))
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    assert_eq!(texts.len(), 5, "the five LD samples");
    texts
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn damaged_ld_files_never_panic(
        which in 0usize..5,
        drops in prop::collection::vec(any::<prop::sample::Index>(), 0..4),
        rewires in prop::collection::vec((any::<prop::sample::Index>(), 1u32..60), 0..4),
    ) {
        let all = samples();
        let text = &all[which % all.len()];
        let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
        for (at, id) in &rewires {
            let wires: Vec<usize> = (0..lines.len()).filter(|&i| lines[i].contains("refLocalId=\"")).collect();
            if wires.is_empty() {
                break;
            }
            let i = wires[at.index(wires.len())];
            let start = lines[i].find("refLocalId=\"").unwrap() + "refLocalId=\"".len();
            let end = start + lines[i][start..].find('"').unwrap();
            lines[i].replace_range(start..end, &id.to_string());
        }
        for at in &drops {
            if lines.len() > 1 {
                let i = at.index(lines.len());
                // Drop a whole one-line element, or a line of a bigger one (then the XML is
                // usually no longer well-formed).
                lines.remove(i);
            }
        }
        if let Ok(i) = import(&lines.join("\n")) {
            for lp in &i.project.ladder {
                let _ = plc_core::ladder::lower(lp);
                let _ = plc_core::ladder::st_view(lp);
                let _ = plc_core::ladder::validate(lp);
            }
            let _ = plc_core::run::run_project(&i.project, &plc_core::run::RunOptions::default());
            let _ = export(&i.project);
        }
    }
}

fn element() -> impl Strategy<Value = plc_core::ladder::Element> {
    use plc_core::ladder::*;
    let var = prop::sample::select(vec!["A", "B", "n", "T1", "", "A+B", "%IX0.1", "C1.Q"]);
    prop_oneof![
        3 => Just(Element::Empty),
        2 => Just(Element::Wire),
        1 => Just(Element::Covered),
        3 => (0u8..4, var.clone()).prop_map(|(k, v)| Element::Contact {
            kind: [ContactKind::NormallyOpen, ContactKind::NormallyClosed, ContactKind::Rising, ContactKind::Falling][k as usize],
            operand: v.to_string(),
        }),
        2 => (0u8..6, var.clone()).prop_map(|(k, v)| Element::Coil {
            kind: [CoilKind::Normal, CoilKind::Negated, CoilKind::Set, CoilKind::Reset, CoilKind::Rising, CoilKind::Falling][k as usize],
            operand: v.to_string(),
        }),
        2 => (prop::sample::select(vec!["TON", "CTU", "SR", "GT", "ADD", "Nope", ""]), 0u32..5, prop::option::of(0u32..6), any::<bool>(), var)
            .prop_map(|(t, h, w, en, v)| {
                let mut b = Block::new(t, if t == "TON" || t == "CTU" || t == "SR" { Some("T1") } else { None });
                b.height = h;
                b.inputs = vec![Pin::operand("PT", v), Pin { name: "R".into(), operand: String::new(), wired_row: w }];
                b.outputs = vec![Pin::operand("Q", v)];
                if en {
                    b.power_in = Some("EN".into());
                    b.power_out = Some("Q".into());
                }
                Element::Block(b)
            }),
        1 => Just(Element::Jump { label: "L".into() }),
        1 => Just(Element::Return),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, failure_persistence: None, ..ProptestConfig::default() })]

    /// Any grid a damaged project file can hold: checked, lowered, viewed, exported and
    /// imported again without a panic.
    #[test]
    fn any_grid_is_handled_without_panic(
        rows in prop::collection::vec(prop::collection::vec((element(), any::<bool>()), 0..5), 0..5),
        label in any::<bool>(),
    ) {
        use plc_core::ladder::*;
        let cells: Vec<Vec<Cell>> = rows
            .into_iter()
            .map(|r| r.into_iter().map(|(element, link_down)| Cell { element, link_down }).collect())
            .collect();
        let rung = Rung { comment: "c *) ]]>".into(), label: label.then(|| "L".to_string()), cells };
        let p = LadderPou {
            name: "Main".into(),
            kind: LadderPouKind::Program,
            declarations: "VAR A : BOOL; B : BOOL; n : INT; T1 : TON; END_VAR".into(),
            rungs: vec![rung.clone(), rung],
        };
        let _ = validate(&p);
        let _ = lower(&p);
        let _ = st_view_pou(&p);
        let mut project = plc_core::project::Project::new("fuzz");
        project.ladder = vec![p];
        let _ = plc_core::run::run_project(&project, &plc_core::run::RunOptions::default());
        let xml = export(&project);
        let _ = import(&xml);
    }
}
