//! Project → PLCopen XML (TC6 0201).

use super::xml::esc;
use crate::ladder::LadderPouKind;
use crate::project::Project;
use crate::syntax::ast::{
    ArrayInitElement, Initializer, Item, PouKind, TypeRef, VarBlock, VarSection,
};
use std::fmt::Write;

const ELEMENTARY: &[&str] = &[
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL",
    "TIME", "DATE", "DT", "TOD", "BYTE", "WORD", "DWORD", "LWORD", "LTIME",
];

fn slice(src: &str, span: crate::diagnostics::Span) -> &str {
    src.get(span.start as usize..span.end as usize).unwrap_or("")
}

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

fn cdata(text: &str) -> String {
    format!("<![CDATA[{}]]>", text.replace("]]>", "]]]]><![CDATA[>"))
}

fn section_tag(s: VarSection) -> &'static str {
    match s {
        VarSection::Var => "localVars",
        VarSection::Input => "inputVars",
        VarSection::Output => "outputVars",
        VarSection::InOut => "inOutVars",
        VarSection::Global => "globalVars",
        VarSection::External => "externalVars",
        VarSection::Temp => "tempVars",
    }
}

/// One `VAR…` block as an interface section element.
pub(crate) fn vars_xml(b: &VarBlock, src: &str, tag: &str, indent: &str) -> String {
    let mut out = format!("{indent}<{tag}");
    if b.retain {
        out.push_str(" retain=\"true\"");
    }
    if b.constant {
        out.push_str(" constant=\"true\"");
    }
    out.push_str(">\n");
    for d in &b.decls {
        for n in &d.names {
            let _ = write!(out, "{indent}  <variable name=\"{}\"", esc(&n.name));
            if let Some(loc) = &d.location {
                let _ = write!(out, " address=\"{}\"", esc(&loc.text));
            }
            let _ = write!(out, ">\n{indent}    <type>{}</type>\n", type_xml(&d.ty, src));
            if let Some(init) = &d.init {
                let _ = writeln!(
                    out,
                    "{indent}    <initialValue>{}</initialValue>",
                    init_xml(init, src)
                );
            }
            if let Some(c) = d.comment.as_deref().filter(|c| !c.is_empty()) {
                let _ = writeln!(out, "{indent}    <documentation>\n{indent}      <xhtml:p>{}</xhtml:p>\n{indent}    </documentation>", cdata(c));
            }
            let _ = writeln!(out, "{indent}  </variable>");
        }
    }
    let _ = writeln!(out, "{indent}</{tag}>");
    out
}

fn type_xml(t: &TypeRef, src: &str) -> String {
    match t {
        TypeRef::Named(id) => {
            let up = id.name.to_ascii_uppercase();
            let up = match up.as_str() {
                "DATE_AND_TIME" => "DT".to_string(),
                "TIME_OF_DAY" => "TOD".to_string(),
                _ => up,
            };
            if ELEMENTARY.contains(&up.as_str()) {
                format!("<{up}/>")
            } else if up == "STRING" || up == "WSTRING" {
                format!("<{}/>", up.to_ascii_lowercase())
            } else {
                format!("<derived name=\"{}\"/>", esc(&id.name))
            }
        }
        TypeRef::String { wide, length, .. } => {
            let tag = if *wide { "wstring" } else { "string" };
            match length {
                Some(l) => format!("<{tag} length=\"{}\"/>", esc(slice(src, l.span))),
                None => format!("<{tag}/>"),
            }
        }
        TypeRef::Array { ranges, element, .. } => {
            let mut out = String::from("<array>");
            for (lo, hi) in ranges {
                let _ = write!(
                    out,
                    "<dimension lower=\"{}\" upper=\"{}\"/>",
                    esc(slice(src, lo.span)),
                    esc(slice(src, hi.span))
                );
            }
            let _ = write!(out, "<baseType>{}</baseType></array>", type_xml(element, src));
            out
        }
        TypeRef::Subrange { base, low, high, .. } => {
            let tag = if base.name.to_ascii_uppercase().starts_with('U') {
                "subrangeUnsigned"
            } else {
                "subrangeSigned"
            };
            format!(
                "<{tag}><range lower=\"{}\" upper=\"{}\"/><baseType>{}</baseType></{tag}>",
                esc(slice(src, low.span)),
                esc(slice(src, high.span)),
                type_xml(&TypeRef::Named(base.clone()), src)
            )
        }
        TypeRef::Enum { values, .. } => {
            let mut out = String::from("<enum><values>");
            for (n, v) in values {
                match v {
                    Some(v) => {
                        let _ = write!(
                            out,
                            "<value name=\"{}\" value=\"{}\"/>",
                            esc(&n.name),
                            esc(slice(src, v.span))
                        );
                    }
                    None => {
                        let _ = write!(out, "<value name=\"{}\"/>", esc(&n.name));
                    }
                }
            }
            out.push_str("</values></enum>");
            out
        }
        TypeRef::Struct { fields, .. } => {
            let block = VarBlock {
                section: VarSection::Var,
                retain: false,
                constant: false,
                decls: fields.clone(),
                span: t.span(),
            };
            let inner = vars_xml(&block, src, "struct", "");
            inner.trim_end().to_string()
        }
    }
}

fn init_xml(init: &Initializer, src: &str) -> String {
    match init {
        Initializer::Expr(e) => format!("<simpleValue value=\"{}\"/>", esc(slice(src, e.span))),
        Initializer::Array { elements, .. } => {
            let mut out = String::from("<arrayValue>");
            for el in elements {
                match el {
                    ArrayInitElement::Single(i) => {
                        let _ = write!(out, "<value>{}</value>", init_xml(i, src));
                    }
                    ArrayInitElement::Repeat { count, value, .. } => {
                        let inner = match value {
                            Some(v) => init_xml(v, src),
                            None => "<simpleValue value=\"\"/>".into(),
                        };
                        let _ = write!(
                            out,
                            "<value repetitionValue=\"{}\">{inner}</value>",
                            esc(slice(src, count.span))
                        );
                    }
                }
            }
            out.push_str("</arrayValue>");
            out
        }
        Initializer::Struct { fields, .. } => {
            let mut out = String::from("<structValue>");
            for (n, v) in fields {
                let _ =
                    write!(out, "<value member=\"{}\">{}</value>", esc(&n.name), init_xml(v, src));
            }
            out.push_str("</structValue>");
            out
        }
    }
}
