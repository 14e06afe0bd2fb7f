#![cfg(not(target_arch = "wasm32"))]
#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Property: for random well-formed ladder POUs, running the LD and running its readable ST
//! view give the same variable values, scan by scan, over random input sequences.
//!
//! The rungs are series of sections (a contact of any kind, 2–3 contacts in parallel, or a
//! block) ending in one or two coils of any kind. Blocks cover the standard FBs with a
//! second BOOL input wired to its own contact (CTU's R, SR's R, RS's R1), a timer, a
//! comparison and an arithmetic function on EN, a user FB on EN/ENO (its ENO or a BOOL
//! output carrying power), a user FB with power on a BOOL pin and a wired second input, and
//! a user FUNCTION with power on its first input.

mod common;

use common::*;
use plc_core::ladder::*;
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::sim::Simulator;
use proptest::prelude::*;

const VARS: [&str; 6] = ["V0", "V1", "V2", "V3", "V4", "V5"];

/// The user POUs the blocks may call.
const USER_POUS: &str = "FUNCTION_BLOCK Gate
VAR_INPUT Step : INT; END_VAR
VAR_OUTPUT Count : INT; Odd : BOOL; END_VAR
Count := Count + Step;
Odd := (Count MOD 2) = 1;
END_FUNCTION_BLOCK

FUNCTION_BLOCK Confirm
VAR_INPUT In : BOOL; Hold : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
VAR Last : BOOL; END_VAR
Q := (In AND Last) OR Hold;
Last := In;
END_FUNCTION_BLOCK

FUNCTION Both : BOOL
VAR_INPUT A : BOOL; B : BOOL; END_VAR
Both := A AND NOT B;
END_FUNCTION
";

#[derive(Debug, Clone, Copy)]
struct ContactSpec {
    kind: u8,
    var: usize,
}

#[derive(Debug, Clone)]
enum BlockSpec {
    Ton(u8),
    Ctu(ContactSpec),
    Sr(ContactSpec),
    Rs(ContactSpec),
    Gt(i8),
    Add,
    Gate(bool),
    Confirm(ContactSpec),
    Both(ContactSpec),
}

#[derive(Debug, Clone)]
enum Section {
    Contact(ContactSpec),
    Parallel(Vec<ContactSpec>),
    Block(BlockSpec),
}

#[derive(Debug, Clone)]
struct RungSpec {
    sections: Vec<Section>,
    coils: Vec<(u8, usize)>,
}

/// Contacts and coils share four variables, so coils often write what contacts read.
const POOL: usize = 4;

fn contact_spec() -> impl Strategy<Value = ContactSpec> {
    (0u8..4, 0usize..POOL).prop_map(|(kind, var)| ContactSpec { kind, var })
}

fn block_spec() -> impl Strategy<Value = BlockSpec> {
    prop_oneof![
        (2u8..6).prop_map(BlockSpec::Ton),
        contact_spec().prop_map(BlockSpec::Ctu),
        contact_spec().prop_map(BlockSpec::Sr),
        contact_spec().prop_map(BlockSpec::Rs),
        (-2i8..4).prop_map(BlockSpec::Gt),
        Just(BlockSpec::Add),
        any::<bool>().prop_map(BlockSpec::Gate),
        contact_spec().prop_map(BlockSpec::Confirm),
        contact_spec().prop_map(BlockSpec::Both),
    ]
}

fn section() -> impl Strategy<Value = Section> {
    prop_oneof![
        3 => contact_spec().prop_map(Section::Contact),
        2 => prop::collection::vec(contact_spec(), 2..=3).prop_map(Section::Parallel),
        3 => block_spec().prop_map(Section::Block),
    ]
}

fn rung_spec() -> impl Strategy<Value = RungSpec> {
    (
        contact_spec(),
        prop::collection::vec(section(), 0..4),
        prop::collection::vec((0u8..6, 0usize..POOL), 1..=2),
    )
        .prop_map(|(first, rest, coils)| {
            let mut sections = vec![Section::Contact(first)];
            sections.extend(rest);
            RungSpec { sections, coils }
        })
}

fn contact(c: ContactSpec) -> Element {
    let kind = [
        ContactKind::NormallyOpen,
        ContactKind::NormallyClosed,
        ContactKind::Rising,
        ContactKind::Falling,
    ][c.kind as usize % 4];
    Element::Contact { kind, operand: VARS[c.var].to_string() }
}

/// The block of a spec at rung `r`, column `c`; `wired` is the contact for its second BOOL
/// input when the rung's wiring row is still free (else the input reads a variable).
fn block(
    spec: &BlockSpec,
    r: usize,
    c: usize,
    wiring_free: bool,
    decls: &mut String,
) -> (Block, Option<ContactSpec>) {
    let name = |t: &str| format!("{t}_{r}_{c}");
    let second = |b: &mut Block, pin: &str, k: ContactSpec| -> Option<ContactSpec> {
        if wiring_free {
            b.height = 4;
            b.inputs.insert(0, Pin::wired(pin, 3));
            Some(k)
        } else {
            b.inputs.insert(0, Pin::operand(pin, VARS[k.var]));
            None
        }
    };
    let mut fb = |t: &str| {
        let inst = name(t);
        decls.push_str(&format!("    {inst} : {t};\n"));
        Block::new(t, Some(&inst))
    };
    match spec {
        BlockSpec::Ton(pt) => {
            let mut b = fb("TON");
            b.inputs = vec![Pin::operand("PT", &format!("T#{}ms", 10 * *pt as u32))];
            (b, None)
        }
        BlockSpec::Ctu(k) => {
            let mut b = fb("CTU");
            b.inputs = vec![Pin::operand("PV", "2")];
            b.outputs = vec![Pin::operand("CV", "n")];
            let w = second(&mut b, "R", *k);
            (b, w)
        }
        BlockSpec::Sr(k) => {
            let mut b = fb("SR");
            let w = second(&mut b, "R", *k);
            (b, w)
        }
        BlockSpec::Rs(k) => {
            let mut b = fb("RS");
            let w = second(&mut b, "R1", *k);
            (b, w)
        }
        BlockSpec::Gt(limit) => {
            let mut b = Block::new("GT", None);
            b.inputs = vec![Pin::operand("IN1", "n"), Pin::operand("IN2", &limit.to_string())];
            (b, None)
        }
        BlockSpec::Add => {
            let mut b = Block::new("ADD", None);
            b.inputs = vec![Pin::operand("IN1", "n"), Pin::operand("IN2", "1")];
            b.outputs = vec![Pin::operand("OUT", "n")];
            (b, None)
        }
        BlockSpec::Gate(odd) => {
            let mut b = fb("Gate");
            b.inputs = vec![Pin::operand("Step", "1")];
            b.outputs = vec![Pin::operand("Count", "m")];
            if *odd {
                b.power_out = Some("Odd".into());
            }
            (b, None)
        }
        BlockSpec::Confirm(k) => {
            let mut b = fb("Confirm");
            b.power_in = Some("In".into());
            b.power_out = Some("Q".into());
            let w = second(&mut b, "Hold", *k);
            (b, w)
        }
        BlockSpec::Both(k) => {
            let mut b = Block::new("Both", None);
            b.power_in = Some("A".into());
            b.power_out = Some("OUT".into());
            let w = second(&mut b, "B", *k);
            (b, w)
        }
    }
}

/// Lays a rung spec onto a 5-row grid: parallel contacts on rows 0–2, the one wired block
/// input per rung on row 3, coils in the last column.
fn build(r: usize, spec: &RungSpec, decls: &mut String) -> Rung {
    let cols = spec.sections.len() + 1;
    let mut rung = Rung::new(5, cols as u32);
    let mut wiring_free = true;
    for (c, s) in spec.sections.iter().enumerate() {
        match s {
            Section::Contact(k) => rung.cells[0][c].element = contact(*k),
            Section::Parallel(ks) => {
                for (row, k) in ks.iter().enumerate() {
                    rung.cells[row][c].element = contact(*k);
                    if row + 1 < ks.len() {
                        rung.cells[row][c].link_down = true;
                        rung.cells[row][c + 1].link_down = true;
                    }
                }
            }
            Section::Block(b) => {
                let (blk, wired) = block(b, r, c, wiring_free, decls);
                for row in 1..blk.height as usize {
                    rung.cells[row][c].element = Element::Covered;
                }
                rung.cells[0][c].element = Element::Block(blk);
                if let Some(k) = wired {
                    wiring_free = false;
                    for w in 0..c - 1 {
                        rung.cells[3][w].element = Element::Wire;
                    }
                    rung.cells[3][c - 1].element = contact(k);
                }
            }
        }
    }
    // Edge coils must be alone on their rung.
    let edge = spec.coils.iter().any(|&(k, _)| k >= 4);
    let coils = if edge { &spec.coils[..1] } else { &spec.coils[..] };
    let last = cols - 1;
    for (row, &(k, var)) in coils.iter().enumerate() {
        let kind = [
            CoilKind::Normal,
            CoilKind::Negated,
            CoilKind::Set,
            CoilKind::Reset,
            CoilKind::Rising,
            CoilKind::Falling,
        ][k as usize];
        rung.cells[row][last].element = Element::Coil { kind, operand: VARS[var].to_string() };
        if row > 0 {
            rung.cells[row - 1][last].link_down = true;
        }
    }
    rung
}

fn build_pou(specs: &[RungSpec]) -> LadderPou {
    let mut decls = String::from("VAR\n    V0 : BOOL; V1 : BOOL; V2 : BOOL; V3 : BOOL; V4 : BOOL; V5 : BOOL;\n    n : INT; m : INT;\n");
    let rungs: Vec<Rung> = specs.iter().enumerate().map(|(r, s)| build(r, s, &mut decls)).collect();
    decls.push_str("END_VAR\n");
    pou(&decls, rungs)
}

fn visible(s: &Simulator) -> serde_json::Map<String, serde_json::Value> {
    let mut m = s.vars_json();
    m.retain(|k, _| !is_hidden_name(k));
    m
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn ladder_and_its_st_view_agree(
        specs in prop::collection::vec(rung_spec(), 1..=3),
        inputs in prop::collection::vec(prop::collection::vec(prop::option::of(any::<bool>()), 6), 1..16),
    ) {
        let p = build_pou(&specs);
        let project = project_with(USER_POUS, p.clone());
        let errors: Vec<_> = validate_with(&p, &project.catalog())
            .into_iter()
            .filter(LadderDiagnostic::is_error)
            .collect();
        prop_assert!(errors.is_empty(), "{errors:?}\n{p:#?}");
        let mut ld = sim_with(USER_POUS, &p);
        let view = st_view_pou(&p);
        let mut st_project = Project::new("view");
        st_project.source = format!("{USER_POUS}\n{view}");
        let mut st = project_simulator(&st_project, Some("Main")).unwrap_or_else(|e| panic!("{e:?}\n{view}"));
        for (scan, values) in inputs.iter().enumerate() {
            for (v, value) in VARS.iter().zip(values) {
                if let Some(on) = value {
                    set(&mut ld, v, *on);
                    set(&mut st, v, *on);
                }
            }
            ld.scan();
            st.scan();
            prop_assert_eq!(visible(&ld), visible(&st), "scan {}\n{}\n{}", scan, view, lower(&p).st);
        }
    }
}
