//! Project → PLCopen XML (TC6 0201).

use super::decl_xml::{cdata, init_xml, section_tag, type_xml, vars_xml};
use super::xml::esc;
use crate::ladder::LadderPouKind;
use crate::project::Project;
use crate::syntax::ast::{Item, PouKind};
use std::fmt::Write;

/// Writes `project` as a TC6 0201 PLCopen XML document.
pub fn export(project: &Project) -> String {
    let src = project.source.as_str();
    let (file, _) = crate::syntax::parse(src);
    let mut data_types = String::new();
    let mut pous = String::new();
    let mut globals = String::new();
    let mut configuration = None;
    // The PROGRAMs written to the file, in order (Petri net POUs are not: PNML carries them).
    let mut programs: Vec<String> = Vec::new();
    for item in &file.items {
        match item {
            Item::Types(defs) => {
                for d in defs {
                    let _ = write!(
                        data_types,
                        "      <dataType name=\"{}\">\n        <baseType>",
                        esc(&d.name.name)
                    );
                    data_types.push_str(&type_xml(&d.ty, src));
                    data_types.push_str("</baseType>\n");
                    if let Some(init) = &d.init {
                        let _ = writeln!(
                            data_types,
                            "        <initialValue>{}</initialValue>",
                            init_xml(init, src)
                        );
                    }
                    data_types.push_str("      </dataType>\n");
                }
            }
            Item::Globals(block) => {
                globals.push_str(&vars_xml(block, src, "globalVars", "        "))
            }
            Item::Configuration(c) => {
                if configuration.is_none() {
                    configuration = Some(c);
                }
            }
            Item::Pou(p) => {
                let pou_type = match p.kind {
                    PouKind::Program => "program",
                    PouKind::Function => "function",
                    PouKind::FunctionBlock => "functionBlock",
                };
                if p.kind == PouKind::Program {
                    programs.push(p.name.name.clone());
                }
                let _ = writeln!(
                    pous,
                    "      <pou name=\"{}\" pouType=\"{pou_type}\">",
                    esc(&p.name.name)
                );
                pous.push_str("        <interface>\n");
                if let Some(rt) = &p.return_type {
                    let _ =
                        writeln!(pous, "          <returnType>{}</returnType>", type_xml(rt, src));
                }
                for b in &p.var_blocks {
                    pous.push_str(&vars_xml(b, src, section_tag(b.section), "          "));
                }
                pous.push_str("        </interface>\n");
                let start = p
                    .var_blocks
                    .last()
                    .map(|b| b.span.end)
                    .or_else(|| p.return_type.as_ref().map(|t| t.span().end))
                    .unwrap_or(p.name.span.end) as usize;
                let end = p.span.end as usize;
                let raw = src.get(start..end).unwrap_or("");
                let body = match raw.to_ascii_uppercase().rfind("END_") {
                    Some(k) => &raw[..k],
                    None => raw,
                };
                let body = body.trim_matches(|c| c == '\n' || c == '\r');
                let language = if p.il.is_some() { "IL" } else { "ST" };
                let _ =
                    write!(pous, "        <body>\n          <{language}>\n            <xhtml:p>");
                pous.push_str(&cdata(body));
                let _ = writeln!(
                    pous,
                    "</xhtml:p>\n          </{language}>\n        </body>\n      </pou>"
                );
            }
        }
    }
    for lp in &project.ladder {
        if lp.kind == LadderPouKind::Program {
            programs.push(lp.name.clone());
        }
        pous.push_str(&super::ld_export::ld_pou_xml(lp));
    }
    for net in &project.networks {
        if net.kind == crate::network::NetworkPouKind::Program {
            programs.push(net.name.clone());
        }
        pous.push_str(&super::network_export::network_pou_xml(net));
    }
    let name = esc(&project.name);
    let mut out = String::new();
    out.push_str("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n");
    out.push_str("<project xmlns=\"http://www.plcopen.org/xml/tc6_0201\" xmlns:xhtml=\"http://www.w3.org/1999/xhtml\" xmlns:xsd=\"http://www.w3.org/2001/XMLSchema\">\n");
    out.push_str("  <fileHeader companyName=\"PLC trainer\" productName=\"PLC trainer\" productVersion=\"1\" creationDateTime=\"1970-01-01T00:00:00\"/>\n");
    let _ = writeln!(
        out,
        "  <contentHeader name=\"{name}\" modificationDateTime=\"1970-01-01T00:00:00\">"
    );
    out.push_str("    <coordinateInfo>\n      <fbd>\n        <scaling x=\"10\" y=\"10\"/>\n      </fbd>\n      <ld>\n        <scaling x=\"10\" y=\"10\"/>\n      </ld>\n      <sfc>\n        <scaling x=\"10\" y=\"10\"/>\n      </sfc>\n    </coordinateInfo>\n  </contentHeader>\n");
    out.push_str("  <types>\n");
    if data_types.is_empty() {
        out.push_str("    <dataTypes/>\n");
    } else {
        let _ = write!(out, "    <dataTypes>\n{data_types}    </dataTypes>\n");
    }
    if pous.is_empty() {
        out.push_str("    <pous/>\n");
    } else {
        let _ = write!(out, "    <pous>\n{pous}    </pous>\n");
    }
    out.push_str("  </types>\n  <instances>\n    <configurations>\n");
    if let Some(config) = configuration {
        // The source's own configuration, with its tasks and program instances.
        out.push_str(&super::tasks::configuration_xml(config, src, &globals));
        out.push_str("    </configurations>\n  </instances>\n");
        out.push_str(&trainer_data(project, None));
        out.push_str("</project>\n");
        return out;
    }
    out.push_str("      <configuration name=\"config\">\n        <resource name=\"resource1\">\n");
    // The task runs the PROGRAM the settings choose, when it is in the file.
    let chosen = project
        .settings
        .program
        .as_ref()
        .and_then(|p| programs.iter().find(|n| n.eq_ignore_ascii_case(p)))
        .cloned();
    if let Some(prog) = chosen.as_ref().or(programs.first()) {
        let _ = writeln!(
            out,
            "          <task name=\"task0\" priority=\"0\" interval=\"T#{}ms\">",
            project.settings.cycle_ms
        );
        let _ = writeln!(
            out,
            "            <pouInstance name=\"instance0\" typeName=\"{}\"/>",
            esc(prog)
        );
        out.push_str("          </task>\n");
    }
    out.push_str("        </resource>\n");
    out.push_str(&globals);
    out.push_str("      </configuration>\n    </configurations>\n  </instances>\n");
    out.push_str(&trainer_data(project, chosen.as_deref()));
    out.push_str("</project>\n");
    out
}

/// The trainer's own settings as project `addData` (other tools discard it): the PROGRAM
/// chosen to run, the plant and the scene; empty when there is none of them.
fn trainer_data(project: &Project, program: Option<&str>) -> String {
    let plant = project.settings.plant.as_deref();
    if program.is_none() && plant.is_none() && project.scene.is_none() {
        return String::new();
    }
    let mut out = format!(
        "  <addData>\n    <data name=\"{}\" handleUnknown=\"discard\">\n      <trainer",
        super::import::TRAINER_DATA
    );
    if let Some(p) = program {
        let _ = write!(out, " program=\"{}\"", esc(p));
    }
    if let Some(p) = plant {
        let _ = write!(out, " plant=\"{}\"", esc(p));
    }
    match &project.scene {
        Some(scene) => {
            let json = serde_json::to_string(scene).unwrap_or_default();
            let _ = write!(out, ">\n        <scene>{}</scene>\n      </trainer>\n", cdata(&json));
        }
        None => out.push_str("/>\n"),
    }
    out.push_str("    </data>\n  </addData>\n");
    out
}
