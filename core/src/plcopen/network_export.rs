//! Network POU → `<pou>` with its `<LD>`, `<FBD>` or `<SFC>` body written back as it came: every
//! element at its position and size, its pins at their relative positions, its wires with
//! the points they are drawn through, and its execution order.

use std::fmt::Write;

use super::decl_xml::{cdata, section_tag, type_xml, vars_xml};
use super::ld_export::{coil_attrs, contact_attrs};
use super::xml::esc;
use crate::network::{NetElement, NetKind, NetworkPou, NetworkPouKind, Pin};
use crate::network::{PinModifier, SfcActionBody, SfcCondition};
use crate::syntax::ast::Item;

/// One network POU as a `<pou>` element.
pub(crate) fn network_pou_xml(net: &NetworkPou) -> String {
    let pou_type = match net.kind {
        NetworkPouKind::Program => "program",
        NetworkPouKind::FunctionBlock => "functionBlock",
        NetworkPouKind::Function => "function",
    };
    let mut out = format!(
        "      <pou name=\"{}\" pouType=\"{pou_type}\">\n        <interface>\n",
        esc(&net.name)
    );
    let wrapped = format!("{}\n{}\nEND_{}\n", net.header(), net.declarations, net.kind.keyword());
    let (file, _) = crate::syntax::parse(&wrapped);
    for item in &file.items {
        if let Item::Pou(p) = item {
            if let Some(rt) = &p.return_type {
                let _ =
                    writeln!(out, "          <returnType>{}</returnType>", type_xml(rt, &wrapped));
            }
            for b in &p.var_blocks {
                out.push_str(&vars_xml(b, &wrapped, section_tag(b.section), "          "));
            }
        }
    }
    let tag = net.language.name();
    out.push_str("        </interface>\n");
    named_bodies(&mut out, "actions", "action", &net.actions);
    named_bodies(&mut out, "transitions", "transition", &net.transitions);
    let _ = writeln!(out, "        <body>\n          <{tag}>");
    for e in &net.elements {
        element_xml(&mut out, e);
    }
    let _ = writeln!(out, "          </{tag}>\n        </body>\n      </pou>");
    out
}

/// An SFC POU's `<actions>` or `<transitions>`, each body in ST.
fn named_bodies(out: &mut String, list: &str, item: &str, bodies: &[crate::network::NamedBody]) {
    if bodies.is_empty() {
        return;
    }
    let _ = writeln!(out, "        <{list}>");
    for b in bodies {
        let _ = writeln!(
            out,
            "          <{item} name=\"{}\">\n            <body>\n              <ST>\n                <xhtml:p>{}</xhtml:p>\n              </ST>\n            </body>\n          </{item}>",
            esc(&b.name),
            cdata(&b.st)
        );
    }
    let _ = writeln!(out, "        </{list}>");
}

/// An inline ST body (`<inline><ST>…</ST></inline>`) at `indent`.
fn inline_st(out: &mut String, st: &str, indent: &str) {
    let _ = writeln!(
        out,
        "{indent}<inline>\n{indent}  <ST>\n{indent}    <xhtml:p>{}</xhtml:p>\n{indent}  </ST>\n{indent}</inline>",
        cdata(st)
    );
}

/// A number as PLCopen writes coordinates (whole numbers without a fraction).
fn n(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        format!("{v}")
    }
}

const I: &str = "            ";

fn position(out: &mut String, e: &NetElement) {
    let _ = writeln!(out, "{I}  <position x=\"{}\" y=\"{}\"/>", n(e.x), n(e.y));
}

/// A `connectionPointIn` with its wires.
fn point_in(out: &mut String, pin: &Pin, indent: &str) {
    let _ = writeln!(out, "{indent}<connectionPointIn>");
    let _ = writeln!(out, "{indent}  <relPosition x=\"{}\" y=\"{}\"/>", n(pin.dx), n(pin.dy));
    for w in &pin.wires {
        let param = w
            .param
            .as_ref()
            .map(|p| format!(" formalParameter=\"{}\"", esc(p)))
            .unwrap_or_default();
        if w.points.is_empty() {
            let _ = writeln!(out, "{indent}  <connection refLocalId=\"{}\"{param}/>", esc(&w.from));
        } else {
            let _ = writeln!(out, "{indent}  <connection refLocalId=\"{}\"{param}>", esc(&w.from));
            for (x, y) in &w.points {
                let _ = writeln!(out, "{indent}    <position x=\"{}\" y=\"{}\"/>", n(*x), n(*y));
            }
            let _ = writeln!(out, "{indent}  </connection>");
        }
    }
    let _ = writeln!(out, "{indent}</connectionPointIn>");
}

/// A `connectionPointOut`.
fn point_out(out: &mut String, pin: &Pin, indent: &str, formal: bool) {
    let attr =
        if formal { format!(" formalParameter=\"{}\"", esc(&pin.name)) } else { String::new() };
    let _ = writeln!(out, "{indent}<connectionPointOut{attr}>");
    let _ = writeln!(out, "{indent}  <relPosition x=\"{}\" y=\"{}\"/>", n(pin.dx), n(pin.dy));
    let _ = writeln!(out, "{indent}</connectionPointOut>");
}

/// The element's connection points that are not a block's (inputs, then outputs).
fn points(out: &mut String, e: &NetElement) {
    let indent = format!("{I}  ");
    for p in &e.inputs {
        point_in(out, p, &indent);
    }
    for p in &e.outputs {
        point_out(out, p, &indent, false);
    }
}

fn size(e: &NetElement) -> String {
    let order =
        if e.order > 0 { format!(" executionOrderId=\"{}\"", e.order) } else { String::new() };
    format!(" height=\"{}\" width=\"{}\"{order}", n(e.height), n(e.width))
}

fn element_xml(out: &mut String, e: &NetElement) {
    let id = esc(&e.id);
    match &e.kind {
        // Elements of several outputs, each named (`formalParameter`).
        NetKind::LeftRail
        | NetKind::RightRail
        | NetKind::SelectionDivergence
        | NetKind::SelectionConvergence
        | NetKind::SimultaneousDivergence
        | NetKind::SimultaneousConvergence => {
            let tag = match e.kind {
                NetKind::LeftRail => "leftPowerRail",
                NetKind::RightRail => "rightPowerRail",
                NetKind::SelectionDivergence => "selectionDivergence",
                NetKind::SelectionConvergence => "selectionConvergence",
                NetKind::SimultaneousDivergence => "simultaneousDivergence",
                _ => "simultaneousConvergence",
            };
            let _ = writeln!(out, "{I}<{tag} localId=\"{id}\"{}>", size(e));
            position(out, e);
            let indent = format!("{I}  ");
            for p in &e.inputs {
                point_in(out, p, &indent);
            }
            for p in &e.outputs {
                point_out(out, p, &indent, true);
            }
            let _ = writeln!(out, "{I}</{tag}>");
        }
        NetKind::Contact { operand, contact } => {
            let attrs = contact_attrs(*contact);
            let _ = writeln!(out, "{I}<contact localId=\"{id}\"{}{attrs}>", size(e));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}  <variable>{}</variable>\n{I}</contact>", esc(operand));
        }
        NetKind::Coil { operand, coil } => {
            let attrs = coil_attrs(*coil);
            let _ = writeln!(out, "{I}<coil localId=\"{id}\"{}{attrs}>", size(e));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}  <variable>{}</variable>\n{I}</coil>", esc(operand));
        }
        NetKind::Block { type_name, instance } => {
            let inst = instance
                .as_ref()
                .map(|i| format!(" instanceName=\"{}\"", esc(i)))
                .unwrap_or_default();
            let _ = writeln!(
                out,
                "{I}<block localId=\"{id}\" typeName=\"{}\"{inst}{}>",
                esc(type_name),
                size(e)
            );
            position(out, e);
            let pins = |out: &mut String, tag: &str, list: Vec<&Pin>, input: bool| {
                let _ = writeln!(out, "{I}  <{tag}>");
                for p in list {
                    let modifier = match p.modifier {
                        Some(PinModifier::Negated) => " negated=\"true\"",
                        Some(PinModifier::Rising) => " edge=\"rising\"",
                        Some(PinModifier::Falling) => " edge=\"falling\"",
                        None => "",
                    };
                    let _ = writeln!(
                        out,
                        "{I}    <variable formalParameter=\"{}\"{modifier}>",
                        esc(&p.name)
                    );
                    let indent = format!("{I}      ");
                    if input {
                        point_in(out, p, &indent);
                    } else {
                        point_out(out, p, &indent, false);
                    }
                    let _ = writeln!(out, "{I}    </variable>");
                }
                let _ = writeln!(out, "{I}  </{tag}>");
            };
            pins(out, "inputVariables", e.inputs.iter().filter(|p| !p.in_out).collect(), true);
            pins(out, "inOutVariables", e.inputs.iter().filter(|p| p.in_out).collect(), true);
            pins(out, "outputVariables", e.outputs.iter().filter(|p| !p.in_out).collect(), false);
            let _ = writeln!(out, "{I}</block>");
        }
        NetKind::InVar { expr } | NetKind::OutVar { expr } | NetKind::InOutVar { expr } => {
            let tag = match e.kind {
                NetKind::InVar { .. } => "inVariable",
                NetKind::OutVar { .. } => "outVariable",
                _ => "inOutVariable",
            };
            let _ = writeln!(out, "{I}<{tag} localId=\"{id}\"{} negated=\"false\">", size(e));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}  <expression>{}</expression>\n{I}</{tag}>", esc(expr));
        }
        NetKind::Comment { text } => {
            let _ = writeln!(out, "{I}<comment localId=\"{id}\"{}>", size(e));
            position(out, e);
            let _ = writeln!(
                out,
                "{I}  <content>\n{I}    <xhtml:p>{}</xhtml:p>\n{I}  </content>\n{I}</comment>",
                cdata(text)
            );
        }
        NetKind::Label { label } | NetKind::Jump { label } => {
            let tag = if matches!(e.kind, NetKind::Label { .. }) { "label" } else { "jump" };
            let _ =
                writeln!(out, "{I}<{tag} localId=\"{id}\"{} label=\"{}\">", size(e), esc(label));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}</{tag}>");
        }
        NetKind::Return => {
            let _ = writeln!(out, "{I}<return localId=\"{id}\"{}>", size(e));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}</return>");
        }
        NetKind::Step { name, initial } => {
            let _ = writeln!(
                out,
                "{I}<step localId=\"{id}\"{} name=\"{}\" initialStep=\"{initial}\">",
                size(e),
                esc(name)
            );
            position(out, e);
            let indent = format!("{I}  ");
            for p in &e.inputs {
                point_in(out, p, &indent);
            }
            for p in &e.outputs {
                let tag = if p.name == "action" {
                    "connectionPointOutAction"
                } else {
                    "connectionPointOut"
                };
                let _ = writeln!(out, "{indent}<{tag} formalParameter=\"\">");
                let _ =
                    writeln!(out, "{indent}  <relPosition x=\"{}\" y=\"{}\"/>", n(p.dx), n(p.dy));
                let _ = writeln!(out, "{indent}</{tag}>");
            }
            let _ = writeln!(out, "{I}</step>");
        }
        NetKind::Transition { condition, negated, priority } => {
            let priority = priority.map(|p| format!(" priority=\"{p}\"")).unwrap_or_default();
            let _ = writeln!(out, "{I}<transition localId=\"{id}\"{}{priority}>", size(e));
            position(out, e);
            let indent = format!("{I}  ");
            for p in e.inputs.iter().filter(|p| p.name != "condition") {
                point_in(out, p, &indent);
            }
            for p in &e.outputs {
                point_out(out, p, &indent, false);
            }
            let neg = if *negated { " negated=\"true\"" } else { "" };
            let _ = writeln!(out, "{indent}<condition{neg}>");
            let inner = format!("{indent}  ");
            match condition {
                SfcCondition::Inline { st } => inline_st(out, st, &inner),
                SfcCondition::Reference { name } => {
                    let _ = writeln!(out, "{inner}<reference name=\"{}\"/>", esc(name));
                }
                SfcCondition::Wired => {
                    for p in e.inputs.iter().filter(|p| p.name == "condition") {
                        point_in(out, p, &inner);
                    }
                }
            }
            let _ = writeln!(out, "{indent}</condition>\n{I}</transition>");
        }
        NetKind::JumpStep { target } => {
            let _ = writeln!(
                out,
                "{I}<jumpStep localId=\"{id}\"{} targetName=\"{}\">",
                size(e),
                esc(target)
            );
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}</jumpStep>");
        }
        NetKind::ActionBlock { actions } => {
            let _ = writeln!(out, "{I}<actionBlock localId=\"{id}\"{}>", size(e));
            position(out, e);
            let indent = format!("{I}  ");
            for p in &e.inputs {
                point_in(out, p, &indent);
            }
            for a in actions {
                // Beremiz numbers the rows 0 and places them itself.
                let mut attrs = format!(" localId=\"0\" qualifier=\"{}\"", esc(&a.qualifier));
                if let Some(d) = &a.duration {
                    let _ = write!(attrs, " duration=\"{}\"", esc(d));
                }
                if let Some(i) = &a.indicator {
                    let _ = write!(attrs, " indicator=\"{}\"", esc(i));
                }
                let _ = writeln!(out, "{indent}<action{attrs}>");
                let _ = writeln!(out, "{indent}  <relPosition x=\"0\" y=\"0\"/>");
                match &a.action {
                    SfcActionBody::Reference { name } => {
                        let _ = writeln!(out, "{indent}  <reference name=\"{}\"/>", esc(name));
                    }
                    SfcActionBody::Inline { st } => inline_st(out, st, &format!("{indent}  ")),
                }
                let _ = writeln!(out, "{indent}</action>");
            }
            let _ = writeln!(out, "{I}</actionBlock>");
        }
        NetKind::Connector { name } | NetKind::Continuation { name } => {
            let tag = if matches!(e.kind, NetKind::Connector { .. }) {
                "connector"
            } else {
                "continuation"
            };
            let _ = writeln!(out, "{I}<{tag} name=\"{}\" localId=\"{id}\"{}>", esc(name), size(e));
            position(out, e);
            points(out, e);
            let _ = writeln!(out, "{I}</{tag}>");
        }
    }
}
