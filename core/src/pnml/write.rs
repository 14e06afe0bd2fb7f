//! PNML export of a Petri net POU.

use std::fmt::Write as _;

use super::TOOL;
use crate::petri::model::{PetriPou, Position, SyncStyle};

fn esc(s: &str) -> String {
    quick_xml::escape::escape(s).into_owned()
}

fn graphics(out: &mut String, indent: &str, pos: Option<Position>) {
    if let Some(p) = pos {
        let _ =
            writeln!(out, "{indent}<graphics><position x=\"{}\" y=\"{}\"/></graphics>", p.x, p.y);
    }
}

fn name(out: &mut String, indent: &str, name: &str) {
    if !name.is_empty() {
        let _ = writeln!(out, "{indent}<name><text>{}</text></name>", esc(name));
    }
}

fn text_element(out: &mut String, indent: &str, tag: &str, text: &str) {
    if !text.is_empty() {
        let _ = writeln!(out, "{indent}<{tag}>{}</{tag}>", esc(text));
    }
}

/// The POU as a PNML document (a P/T net with our `toolspecific` elements).
pub fn export(pou: &PetriPou) -> String {
    let net = &pou.net;
    let mut s = String::new();
    s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    s.push_str("<pnml xmlns=\"http://www.pnml.org/version-2009/grammar/pnml\">\n");
    let _ = writeln!(
        s,
        "  <net id=\"{}\" type=\"http://www.pnml.org/version-2009/grammar/ptnet\">",
        esc(&pou.name)
    );
    name(&mut s, "    ", &pou.name);
    let _ = writeln!(s, "    <toolspecific tool=\"{TOOL}\" version=\"1\">");
    text_element(&mut s, "      ", "declarations", &pou.declarations);
    text_element(&mut s, "      ", "prologue", &pou.prologue);
    text_element(&mut s, "      ", "epilogue", &pou.epilogue);
    let sync = match pou.options.sync {
        SyncStyle::StepVariables => "stepVariables",
        SyncStyle::Flags => "flags",
    };
    let _ = writeln!(s, "      <options retain=\"{}\" sync=\"{sync}\"/>", pou.options.retain);
    if let Some(e) = &net.emergency {
        let _ = writeln!(
            s,
            "      <emergency place=\"{}\"><condition>{}</condition></emergency>",
            esc(&e.place),
            esc(&e.condition)
        );
    }
    for m in &net.macro_places {
        let _ = writeln!(s, "      <macroPlace id=\"{}\">", esc(&m.id));
        name(&mut s, "        ", &m.name);
        graphics(&mut s, "        ", m.position);
        text_element(&mut s, "        ", "comment", &m.comment);
        for p in &m.places {
            let _ = writeln!(s, "        <place ref=\"{}\"/>", esc(p));
        }
        s.push_str("      </macroPlace>\n");
    }
    for p in &net.processes {
        let _ = writeln!(
            s,
            "      <process name=\"{}\" stepVariable=\"{}\">",
            esc(&p.name),
            esc(&p.step_variable)
        );
        for id in &p.places {
            let _ = writeln!(s, "        <place ref=\"{}\"/>", esc(id));
        }
        s.push_str("      </process>\n");
    }
    s.push_str("    </toolspecific>\n");
    s.push_str("    <page id=\"page\">\n");
    for p in &net.places {
        let _ = writeln!(s, "      <place id=\"{}\">", esc(&p.id));
        name(&mut s, "        ", &p.name);
        graphics(&mut s, "        ", p.position);
        if p.tokens > 0 {
            let _ =
                writeln!(s, "        <initialMarking><text>{}</text></initialMarking>", p.tokens);
        }
        let _ = writeln!(s, "        <toolspecific tool=\"{TOOL}\" version=\"1\">");
        let _ = writeln!(s, "          <label>{}</label>", p.label);
        if let Some(c) = p.capacity {
            let _ = writeln!(s, "          <capacity>{c}</capacity>");
        }
        text_element(&mut s, "          ", "actions", &p.actions);
        text_element(&mut s, "          ", "comment", &p.comment);
        s.push_str("        </toolspecific>\n      </place>\n");
    }
    for t in &net.transitions {
        let _ = writeln!(s, "      <transition id=\"{}\">", esc(&t.id));
        name(&mut s, "        ", &t.name);
        graphics(&mut s, "        ", t.position);
        let _ = writeln!(s, "        <toolspecific tool=\"{TOOL}\" version=\"1\">");
        text_element(&mut s, "          ", "guard", &t.guard);
        let _ = writeln!(s, "          <priority>{}</priority>", t.priority);
        text_element(&mut s, "          ", "comment", &t.comment);
        s.push_str("        </toolspecific>\n      </transition>\n");
    }
    for (i, a) in net.arcs.iter().enumerate() {
        let _ = write!(
            s,
            "      <arc id=\"a{}\" source=\"{}\" target=\"{}\"",
            i + 1,
            esc(&a.from),
            esc(&a.to)
        );
        if a.weight == 1 {
            s.push_str("/>\n");
        } else {
            let _ = writeln!(s, "><inscription><text>{}</text></inscription></arc>", a.weight);
        }
    }
    s.push_str("    </page>\n  </net>\n</pnml>\n");
    s
}
