//! Declarations as PLCopen XML: variable sections, types and initial values, shared by the
//! ST export (`export.rs`) and the ladder export (`ld_export.rs`).

use super::xml::esc;
use crate::syntax::ast::{ArrayInitElement, Initializer, TypeRef, VarBlock, VarSection};
use std::fmt::Write;

const ELEMENTARY: &[&str] = &[
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL",
    "TIME", "DATE", "DT", "TOD", "BYTE", "WORD", "DWORD", "LWORD", "LTIME",
];

fn slice(src: &str, span: crate::diagnostics::Span) -> &str {
    src.get(span.start as usize..span.end as usize).unwrap_or("")
}

/// Text in a CDATA section (a `]]>` inside is split).
pub(crate) fn cdata(text: &str) -> String {
    format!("<![CDATA[{}]]>", text.replace("]]>", "]]]]><![CDATA[>"))
}

/// The interface element of a variable section.
pub(crate) fn section_tag(s: VarSection) -> &'static str {
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

/// A type reference as PLCopen XML.
pub(crate) fn type_xml(t: &TypeRef, src: &str) -> String {
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
        TypeRef::Ref { target, .. } => {
            format!("<pointer><baseType>{}</baseType></pointer>", type_xml(target, src))
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

/// An initial value as PLCopen XML.
pub(crate) fn init_xml(init: &Initializer, src: &str) -> String {
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
