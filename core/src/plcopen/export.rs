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
    let mut first_program: Option<String> = None;
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
            Item::Pou(p) => {
                let pou_type = match p.kind {
                    PouKind::Program => "program",
                    PouKind::Function => "function",
                    PouKind::FunctionBlock => "functionBlock",
                };
                if p.kind == PouKind::Program && first_program.is_none() {
                    first_program = Some(p.name.name.clone());
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
                pous.push_str("        <body>\n          <ST>\n            <xhtml:p>");
                pous.push_str(&cdata(body));
                pous.push_str("</xhtml:p>\n          </ST>\n        </body>\n      </pou>\n");
            }
        }
    }
    for lp in &project.ladder {
        if lp.kind == LadderPouKind::Program && first_program.is_none() {
            first_program = Some(lp.name.clone());
        }
        pous.push_str(&super::ld_export::ld_pou_xml(lp));
    }
    for net in &project.networks {
        if net.kind == crate::network::NetworkPouKind::Program && first_program.is_none() {
            first_program = Some(net.name.clone());
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
    out.push_str("  </types>\n  <instances>\n    <configurations>\n      <configuration name=\"config\">\n        <resource name=\"resource1\">\n");
    if let Some(prog) = &first_program {
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
    out.push_str("      </configuration>\n    </configurations>\n  </instances>\n</project>\n");
    out
}
