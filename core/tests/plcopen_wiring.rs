#![allow(clippy::unwrap_used, clippy::expect_used)]
//! PLCopen LD wiring beyond contacts and coils, as Beremiz and OpenPLC Editor write it:
//! data wires from one block's output to another block's input, connector/continuation
//! pairs, in-out pins, and user FBs on EN/ENO or on a BOOL input. Each is imported, run
//! scan by scan, and exported and imported again to the same program.

use plc_core::ladder::{Block, Element, LadderPou, Pin};
use plc_core::plcopen::{export, import};
use plc_core::project::Project;
use plc_core::run::project_simulator;
use plc_core::sim::Simulator;
use plc_core::vm::Value;

/// A project with the ST POUs `st_pous` (`<pou>` elements) and LD program Main.
fn doc(vars: &str, body: &str, st_pous: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="Wiring"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>{st_pous}
    <pou name="Main" pouType="program">
      <interface><localVars>{vars}</localVars></interface>
      <body><LD>{body}</LD></body>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>"#
    )
}

fn var(name: &str, ty: &str) -> String {
    format!(r#"<variable name="{name}"><type><{ty}/></type></variable>"#)
}

fn derived(name: &str, ty: &str) -> String {
    format!(r#"<variable name="{name}"><type><derived name="{ty}"/></type></variable>"#)
}

const RAIL: &str = r#"<leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>"#;

fn contact(id: u32, v: &str, from: &str, y: u32) -> String {
    format!(
        r#"<contact localId="{id}" negated="false"><position x="50" y="{y}"/><connectionPointIn><connection refLocalId="{from}"/></connectionPointIn><connectionPointOut/><variable>{v}</variable></contact>"#
    )
}

fn coil(id: u32, v: &str, from: &str, param: Option<&str>, y: u32) -> String {
    let p = param.map(|p| format!(r#" formalParameter="{p}""#)).unwrap_or_default();
    format!(
        r#"<coil localId="{id}"><position x="400" y="{y}"/><connectionPointIn><connection refLocalId="{from}"{p}/></connectionPointIn><connectionPointOut/><variable>{v}</variable></coil>"#
    )
}

fn in_var(id: u32, expr: &str, y: u32) -> String {
    format!(
        r#"<inVariable localId="{id}"><position x="0" y="{y}"/><connectionPointOut/><expression>{expr}</expression></inVariable>"#
    )
}

/// `<variable formalParameter=…>` wired to `from` (with the source pin, if any).
fn pin(name: &str, from: &str, param: Option<&str>) -> String {
    let p = param.map(|p| format!(r#" formalParameter="{p}""#)).unwrap_or_default();
    format!(
        r#"<variable formalParameter="{name}"><connectionPointIn><connection refLocalId="{from}"{p}/></connectionPointIn></variable>"#
    )
}

fn out_pin(name: &str) -> String {
    format!(r#"<variable formalParameter="{name}"><connectionPointOut/></variable>"#)
}

fn block(
    id: u32,
    ty: &str,
    inst: Option<&str>,
    y: u32,
    inputs: &[String],
    in_outs: &[String],
    outputs: &[&str],
) -> String {
    let inst = inst.map(|i| format!(r#" instanceName="{i}""#)).unwrap_or_default();
    let outs: String = outputs.iter().map(|o| out_pin(o)).collect();
    let io = if in_outs.is_empty() {
        "<inOutVariables/>".to_string()
    } else {
        format!("<inOutVariables>{}</inOutVariables>", in_outs.concat())
    };
    format!(
        r#"<block localId="{id}" typeName="{ty}"{inst}><position x="200" y="{y}"/><inputVariables>{}</inputVariables>{io}<outputVariables>{outs}</outputVariables></block>"#,
        inputs.concat()
    )
}

fn st_fb(name: &str, interface: &str, body: &str) -> String {
    format!(
        r#"<pou name="{name}" pouType="functionBlock"><interface>{interface}</interface><body><ST><xhtml:p><![CDATA[{body}]]></xhtml:p></ST></body></pou>"#
    )
}

fn round_trip(p: &Project) {
    let xml = export(p);
    let back = import(&xml).unwrap_or_else(|e| panic!("re-import: {e}\n{xml}")).project;
    assert_eq!(back.ladder, p.ladder, "{xml}");
    let norm = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    assert_eq!(norm(&back.source), norm(&p.source));
}

fn sim(p: &Project) -> Simulator {
    project_simulator(p, Some("Main")).unwrap_or_else(|e| panic!("{e:?}"))
}

fn on(s: &Simulator, v: &str) -> bool {
    s.read(v).unwrap() == Value::Bool(true)
}

fn int(s: &Simulator, v: &str) -> i128 {
    match s.read(v).unwrap() {
        Value::Int(n, _) => n,
        other => panic!("{v} is {other:?}"),
    }
}

fn blocks(lp: &LadderPou) -> Vec<Block> {
    lp.rungs
        .iter()
        .flat_map(|r| r.cells.iter().flatten())
        .filter_map(|c| match &c.element {
            Element::Block(b) => Some(b.clone()),
            _ => None,
        })
        .collect()
}

/// T1.ET feeds GT.IN1 directly (a data wire from an FB output), and ADD's OUT feeds LT.IN1
/// (a data wire from a function output, which gets a variable of ADD's type). The GT rung is
/// drawn above the TON rung, but must run after it.
#[test]
fn data_wires_between_blocks() {
    let vars = [
        var("Go", "BOOL"),
        var("Done", "BOOL"),
        var("Half", "BOOL"),
        var("Small", "BOOL"),
        var("n", "INT"),
        derived("T1", "TON"),
    ]
    .concat();
    let body = [
        RAIL.to_string(),
        // GT network first in the drawing.
        contact(20, "Go", "1", 0),
        in_var(21, "T#20ms", 20),
        block(
            22,
            "GT",
            None,
            0,
            &[pin("EN", "20", None), pin("IN1", "31", Some("ET")), pin("IN2", "21", None)],
            &[],
            &["ENO", "OUT"],
        ),
        coil(23, "Half", "22", Some("OUT"), 0),
        // TON network.
        contact(30, "Go", "1", 100),
        in_var(32, "T#50ms", 120),
        block(
            31,
            "TON",
            Some("T1"),
            100,
            &[pin("IN", "30", None), pin("PT", "32", None)],
            &[],
            &["Q", "ET"],
        ),
        coil(33, "Done", "31", Some("Q"), 100),
        // ADD → LT network.
        contact(40, "Go", "1", 200),
        in_var(41, "n", 220),
        in_var(42, "1", 240),
        block(
            43,
            "ADD",
            None,
            200,
            &[pin("EN", "40", None), pin("IN1", "41", None), pin("IN2", "42", None)],
            &[],
            &["ENO", "OUT"],
        ),
        in_var(44, "10", 260),
        block(
            45,
            "LT",
            None,
            200,
            &[pin("EN", "43", Some("ENO")), pin("IN1", "43", Some("OUT")), pin("IN2", "44", None)],
            &[],
            &["ENO", "OUT"],
        ),
        coil(46, "Small", "45", Some("OUT"), 200),
    ]
    .concat();
    let i = import(&doc(&vars, &body, "")).unwrap_or_else(|e| panic!("{e}"));
    let p = i.project;
    let lp = &p.ladder[0];
    let bs = blocks(lp);
    assert_eq!(bs[0].type_name, "TON", "the TON rung runs first: {bs:?}");
    let gt = bs.iter().find(|b| b.type_name == "GT").unwrap();
    assert_eq!(gt.inputs[0], Pin::operand("IN1", "T1.ET"));
    let add = bs.iter().find(|b| b.type_name == "ADD").unwrap();
    assert_eq!(add.outputs, vec![Pin::operand("OUT", "ADD_43_OUT")]);
    let lt = bs.iter().find(|b| b.type_name == "LT").unwrap();
    assert_eq!(lt.inputs[0], Pin::operand("IN1", "ADD_43_OUT"));
    assert!(lp.declarations.contains("ADD_43_OUT : INT;"), "{}", lp.declarations);
    // Scan k runs at 10k ms: Half once ET > 20 ms (k = 3), Done once ET >= 50 ms (k = 5).
    let mut s = sim(&p);
    s.write("Go", "TRUE").unwrap();
    s.write("n", "8").unwrap();
    for k in 0..7 {
        s.scan();
        assert_eq!((on(&s, "Half"), on(&s, "Done")), (k >= 3, k >= 5), "scan {k}");
        assert!(on(&s, "Small"), "8 + 1 < 10");
    }
    s.write("n", "9").unwrap();
    s.scan();
    assert!(!on(&s, "Small"), "9 + 1 is not < 10");
    round_trip(&p);
}

/// A latch whose output side is reached through a connector/continuation pair.
#[test]
fn connectors_and_continuations_are_followed() {
    let vars = ["Start", "Stop", "Motor"].map(|v| var(v, "BOOL")).concat();
    let body = [
        RAIL.to_string(),
        contact(2, "Start", "1", 10),
        contact(3, "Motor", "1", 60),
        r#"<connector name="Seal" localId="4"><position x="100" y="10"/><connectionPointIn><connection refLocalId="2"/><connection refLocalId="3"/></connectionPointIn></connector>"#.into(),
        r#"<continuation name="Seal" localId="5"><position x="150" y="10"/><connectionPointOut/></continuation>"#.into(),
        r#"<contact localId="6" negated="true"><position x="200" y="10"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn><connectionPointOut/><variable>Stop</variable></contact>"#.into(),
        coil(7, "Motor", "6", None, 10),
    ]
    .concat();
    let p = import(&doc(&vars, &body, "")).unwrap_or_else(|e| panic!("{e}")).project;
    let (view, _) = plc_core::ladder::st_view(&p.ladder[0]);
    assert_eq!(view.trim(), "Motor := (Start OR Motor) AND NOT Stop;");
    let mut s = sim(&p);
    s.write("Start", "TRUE").unwrap();
    s.scan();
    s.write("Start", "FALSE").unwrap();
    s.scan();
    assert!(on(&s, "Motor"), "sealed in through the continuation");
    s.write("Stop", "TRUE").unwrap();
    s.scan();
    assert!(!on(&s, "Motor"));
    round_trip(&p);
    // A continuation without its connector is named.
    let bad = body.replace(r#"name="Seal" localId="4""#, r#"name="Other" localId="4""#);
    let e = import(&doc(&vars, &bad, "")).unwrap_err().to_string();
    assert!(e.contains("Seal") && e.contains("localId 6"), "{e}");
}

const ACCUMULATE: &str = "Sum := Sum + Add;";

fn accumulate_pou() -> String {
    st_fb(
        "Accumulate",
        r#"<inputVars><variable name="Add"><type><INT/></type></variable></inputVars><inOutVars><variable name="Sum"><type><INT/></type></variable></inOutVars>"#,
        ACCUMULATE,
    )
}

/// A user FB with a VAR_IN_OUT on EN/ENO: the in-out pin gets the variable itself.
#[test]
fn in_out_pins_on_a_user_fb_with_en() {
    let vars =
        [var("Go", "BOOL"), var("Lamp", "BOOL"), var("total", "INT"), derived("A", "Accumulate")]
            .concat();
    let io = r#"<variable formalParameter="Sum"><connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/></variable>"#;
    let body = [
        RAIL.to_string(),
        contact(2, "Go", "1", 0),
        in_var(10, "3", 20),
        r#"<inOutVariable localId="11"><position x="0" y="40"/><connectionPointIn/><connectionPointOut/><expression>total</expression></inOutVariable>"#.into(),
        block(12, "Accumulate", Some("A"), 0, &[pin("EN", "2", None), pin("Add", "10", None)], &[io.to_string()], &["ENO"]),
        r#"<outVariable localId="13"><position x="300" y="40"/><connectionPointIn><connection refLocalId="12" formalParameter="Sum"/></connectionPointIn><expression>total</expression></outVariable>"#.into(),
        coil(14, "Lamp", "12", Some("ENO"), 0),
    ]
    .concat();
    let i = import(&doc(&vars, &body, &accumulate_pou())).unwrap_or_else(|e| panic!("{e}"));
    let p = i.project;
    let acc = &blocks(&p.ladder[0])[0];
    assert_eq!(acc.in_outs, vec![Pin::operand("Sum", "total")]);
    assert_eq!(acc.inputs, vec![Pin::operand("Add", "3")]);
    assert!(acc.outputs.is_empty(), "the outVariable on the in-out is the same variable");
    assert_eq!((acc.power_input(), acc.power_output()), ("EN", "ENO"));
    let mut s = sim(&p);
    s.scan();
    assert_eq!(int(&s, "total"), 0);
    s.write("Go", "TRUE").unwrap();
    s.scan();
    s.scan();
    assert!(on(&s, "Lamp"));
    assert_eq!(int(&s, "total"), 6);
    round_trip(&p);
}

/// A user FB drawn without EN (Beremiz "no execution control"): the rung's power enters at
/// its BOOL input and its BOOL output carries it on; it runs on every scan.
#[test]
fn user_fb_with_power_on_a_bool_pin() {
    let confirm = st_fb(
        "Confirm",
        r#"<inputVars><variable name="In"><type><BOOL/></type></variable></inputVars><outputVars><variable name="Q"><type><BOOL/></type></variable></outputVars><localVars><variable name="Last"><type><BOOL/></type></variable></localVars>"#,
        "Q := In AND Last; Last := In;",
    );
    let vars = [var("Key", "BOOL"), var("Lamp", "BOOL"), derived("C", "Confirm")].concat();
    let body = [
        RAIL.to_string(),
        contact(2, "Key", "1", 0),
        block(3, "Confirm", Some("C"), 0, &[pin("In", "2", None)], &[], &["Q"]),
        coil(4, "Lamp", "3", Some("Q"), 0),
    ]
    .concat();
    let p = import(&doc(&vars, &body, &confirm)).unwrap_or_else(|e| panic!("{e}")).project;
    let c = &blocks(&p.ladder[0])[0];
    assert_eq!((c.power_in.as_deref(), c.power_out.as_deref()), (Some("In"), Some("Q")));
    let mut s = sim(&p);
    s.write("Key", "TRUE").unwrap();
    s.scan();
    assert!(!on(&s, "Lamp"));
    s.scan();
    assert!(on(&s, "Lamp"));
    round_trip(&p);
}

/// A user FB on EN with its BOOL output into a coil: `Lamp := Go AND C.Q`.
#[test]
fn user_fb_on_en_with_a_bool_output_to_a_coil() {
    let fb = st_fb(
        "Above",
        r#"<inputVars><variable name="Level"><type><INT/></type></variable></inputVars><outputVars><variable name="High"><type><BOOL/></type></variable></outputVars>"#,
        "High := Level > 5;",
    );
    let vars =
        [var("Go", "BOOL"), var("Lamp", "BOOL"), var("lvl", "INT"), derived("H", "Above")].concat();
    let body = [
        RAIL.to_string(),
        contact(2, "Go", "1", 0),
        in_var(5, "lvl", 20),
        block(
            3,
            "Above",
            Some("H"),
            0,
            &[pin("EN", "2", None), pin("Level", "5", None)],
            &[],
            &["ENO", "High"],
        ),
        coil(4, "Lamp", "3", Some("High"), 0),
    ]
    .concat();
    let p = import(&doc(&vars, &body, &fb)).unwrap_or_else(|e| panic!("{e}")).project;
    let h = &blocks(&p.ladder[0])[0];
    assert_eq!((h.power_input(), h.power_output()), ("EN", "High"));
    let mut s = sim(&p);
    s.write("lvl", "7").unwrap();
    s.scan();
    assert!(!on(&s, "Lamp"), "not enabled");
    s.write("Go", "TRUE").unwrap();
    s.scan();
    assert!(on(&s, "Lamp"));
    s.write("lvl", "2").unwrap();
    s.scan();
    assert!(!on(&s, "Lamp"));
    round_trip(&p);
}
