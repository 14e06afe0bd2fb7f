//! PLCopen XML → project: interfaces, data types and ST bodies as ST text; LD bodies via
//! [`super::ld_import`].

use super::xml::{self, Node};
use super::{Import, ImportError, ImportNote, SkippedPou};
use crate::ladder::{LadderPou, LadderPouKind};
use crate::project::{Project, Settings, SCHEMA_VERSION};

/// Imports a PLCopen XML (TC6 0201) document.
pub fn import(xml_text: &str) -> Result<Import, ImportError> {
    let root = xml::parse(xml_text).map_err(ImportError::Xml)?;
    if root.name != "project" {
        return Err(ImportError::NotPlcopen(format!(
            "the root element is <{}>, not <project>",
            root.name
        )));
    }
    let mut warnings: Vec<ImportNote> = Vec::new();
    let mut skipped: Vec<SkippedPou> = Vec::new();
    let name = root
        .child("contentHeader")
        .and_then(|h| h.attr("name"))
        .or_else(|| root.child("fileHeader").and_then(|h| h.attr("productName")))
        .filter(|n| !n.trim().is_empty())
        .unwrap_or("Imported")
        .to_string();
    let types = root.child("types");
    let mut source = String::new();

    // Data types.
    let mut type_lines = Vec::new();
    if let Some(dts) = types.and_then(|t| t.child("dataTypes")) {
        for dt in dts.children_named("dataType") {
            let tname = dt.attr("name").unwrap_or("").to_string();
            let err = |message: String| ImportError::DataType { name: tname.clone(), message };
            if tname.is_empty() {
                return Err(err("the dataType has no name".into()));
            }
            let base = dt.child("baseType").ok_or_else(|| err("no <baseType>".into()))?;
            let ty = type_text(base).map_err(err)?;
            let init = match dt.child("initialValue") {
                Some(v) => format!(" := {}", value_text(v).map_err(err)?),
                None => String::new(),
            };
            type_lines.push(format!("    {tname} : {ty}{init};\n"));
        }
    }
    if !type_lines.is_empty() {
        source.push_str("TYPE\n");
        for l in type_lines {
            source.push_str(&l);
        }
        source.push_str("END_TYPE\n\n");
    }

    // Globals of configurations and resources.
    let mut settings = Settings::default();
    let mut globals = String::new();
    if let Some(confs) = root.child("instances").and_then(|i| i.child("configurations")) {
        for conf in confs.children_named("configuration") {
            let cname = conf.attr("name").unwrap_or("config");
            for g in conf.children_named("globalVars") {
                globals.push_str(&var_block(g, "VAR_GLOBAL", "").map_err(|message| {
                    ImportError::Pou { pou: format!("configuration {cname}"), message }
                })?);
            }
            for res in conf.children_named("resource") {
                let rname = res.attr("name").unwrap_or("resource");
                for g in res.children_named("globalVars") {
                    globals.push_str(&var_block(g, "VAR_GLOBAL", "").map_err(|message| {
                        ImportError::Pou { pou: format!("resource {rname}"), message }
                    })?);
                }
                if let Some(ms) = res
                    .children_named("task")
                    .find_map(|t| t.attr("interval").and_then(parse_interval_ms))
                    .filter(|&ms| crate::limits::cycle_ns(ms).is_ok())
                {
                    settings.cycle_ms = ms;
                }
            }
        }
    }
    if !globals.is_empty() {
        source.push_str(&globals);
        source.push('\n');
    }

    // POUs: ST texts and LD declarations first, so LD bodies know every block type.
    let mut ladder = Vec::new();
    let mut bodies = Vec::new();
    if let Some(pous) = types.and_then(|t| t.child("pous")) {
        for pou in pous.children_named("pou") {
            let mut out = PouOut {
                source: &mut source,
                ladder: &mut ladder,
                warnings: &mut warnings,
                skipped: &mut skipped,
            };
            if let Some(body) = import_pou(pou, &mut out)? {
                bodies.push(body);
            }
        }
    }
    let mut project =
        Project { schema: SCHEMA_VERSION, name, source, settings, ladder, petri: Vec::new() };
    let catalog = project.catalog();
    let mut places = Vec::new();
    for (k, (pou_node, body)) in bodies.into_iter().enumerate() {
        let lp = &mut project.ladder[k];
        let ld =
            super::ld_import::import_ld(body, &lp.name, &catalog, &lp.declarations, &mut warnings)?;
        lp.rungs = ld.rungs;
        places.extend(ld.origins.iter().map(|&(cell, (line, column))| crate::build::FilePlace {
            site: crate::build::Site::Ladder { pou: lp.name.clone(), cell: Some(cell) },
            line,
            column,
        }));
        if !ld.declarations.is_empty() {
            lp.declarations.push_str("VAR\n");
            for d in ld.declarations {
                lp.declarations.push_str(&d);
                lp.declarations.push('\n');
            }
            lp.declarations.push_str("END_VAR\n");
            warnings.push(ImportNote::on(pou_node, format!(
                "POU {}: data wires from function outputs got variables of their own (see the last VAR block)",
                lp.name
            )));
        }
    }
    Ok(Import { project, warnings, skipped, places })
}

/// Where [`import_pou`] puts what it reads.
struct PouOut<'o> {
    source: &'o mut String,
    ladder: &'o mut Vec<LadderPou>,
    warnings: &'o mut Vec<ImportNote>,
    skipped: &'o mut Vec<SkippedPou>,
}

/// Imports one POU: ST POUs into `source`, LD POUs into `ladder` with no rungs yet (the POU
/// and its `<LD>` body are returned, to be laid out once every POU is known).
fn import_pou<'a>(
    pou: &'a Node,
    out: &mut PouOut<'_>,
) -> Result<Option<(&'a Node, &'a Node)>, ImportError> {
    let (source, ladder, warnings) = (&mut *out.source, &mut *out.ladder, &mut *out.warnings);
    let name = pou.attr("name").unwrap_or("").to_string();
    let err = |message: String| ImportError::Pou { pou: name.clone(), message };
    if name.is_empty() {
        return Err(ImportError::Pou { pou: "(unnamed)".into(), message: "no name".into() });
    }
    let pou_type = pou.attr("pouType").unwrap_or("program");
    let (keyword, end) = match pou_type {
        "program" => ("PROGRAM", "END_PROGRAM"),
        "functionBlock" => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        "function" => ("FUNCTION", "END_FUNCTION"),
        other => return Err(err(format!("unknown pouType {other:?}"))),
    };
    let mut declarations = String::new();
    let mut return_type = None;
    if let Some(iface) = pou.child("interface") {
        for block in &iface.children {
            let (section, attrs) = match block.name.as_str() {
                "returnType" => {
                    return_type = Some(type_text(block).map_err(err)?);
                    continue;
                }
                "inputVars" => ("VAR_INPUT", ""),
                "outputVars" => ("VAR_OUTPUT", ""),
                "inOutVars" => ("VAR_IN_OUT", ""),
                "localVars" => ("VAR", ""),
                "tempVars" => ("VAR_TEMP", ""),
                "externalVars" => ("VAR_EXTERNAL", ""),
                "globalVars" => ("VAR_GLOBAL", ""),
                "documentation" | "addData" => continue,
                other => {
                    warnings.push(ImportNote::on(
                        block,
                        format!("POU {name}: interface section <{other}> skipped"),
                    ));
                    continue;
                }
            };
            declarations.push_str(&var_block(block, section, attrs).map_err(err)?);
        }
    }
    if pou.child("actions").is_some_and(|a| !a.children.is_empty())
        || pou.child("transitions").is_some_and(|a| !a.children.is_empty())
    {
        warnings.push(ImportNote::on(pou, format!("POU {name}: actions and transitions skipped")));
    }
    let body = pou.child("body").ok_or_else(|| err("no <body>".into()))?;
    let lang = body
        .children
        .iter()
        .find(|c| c.name != "documentation" && c.name != "addData")
        .ok_or_else(|| err("empty <body>".into()))?;
    match lang.name.as_str() {
        "ST" => {
            let text = lang.deep_text().replace("\r\n", "\n");
            let header = pou_header(keyword, &name, pou_type, return_type).map_err(err)?;
            push_pou(source, &header, &declarations, &text, end);
        }
        "FBD" => match super::fbd_import::import_fbd(lang, &name) {
            Ok(fbd) => {
                let header = pou_header(keyword, &name, pou_type, return_type).map_err(err)?;
                let mut declarations = declarations;
                let missing: Vec<&(String, String)> =
                    fbd.instances.iter().filter(|(i, _)| !declares(&declarations, i)).collect();
                if !missing.is_empty() {
                    declarations.push_str("VAR\n");
                    for (inst, ty) in missing {
                        declarations.push_str(&format!("    {inst} : {ty};\n"));
                    }
                    declarations.push_str("END_VAR\n");
                }
                push_pou(source, &header, &declarations, &fbd.statements, end);
                warnings.extend(fbd.notes);
                warnings.push(ImportNote::on(
                    lang,
                    format!("POU {name}: the FBD body runs as ST statements in its execution order (the drawing is not kept yet)"),
                ));
            }
            Err(e) => {
                let reason = format!("its FBD body cannot be imported yet ({e})");
                warnings.push(ImportNote::on(
                    lang,
                    format!("POU {name}: {reason}; the POU was skipped"),
                ));
                out.skipped.push(SkippedPou { name, kind: keyword.to_string(), reason });
            }
        },
        "LD" => {
            let kind =
                match pou_type {
                    "program" => LadderPouKind::Program,
                    "functionBlock" => LadderPouKind::FunctionBlock,
                    _ => return Err(err(
                        "LD functions are not supported yet (only programs and function blocks)"
                            .into(),
                    )),
                };
            ladder.push(LadderPou { name, kind, declarations, rungs: Vec::new() });
            return Ok(Some((pou, lang)));
        }
        other => {
            let reason = format!("{other} bodies are not supported yet");
            warnings
                .push(ImportNote::on(lang, format!("POU {name}: {reason}; the POU was skipped")));
            out.skipped.push(SkippedPou { name, kind: keyword.to_string(), reason });
        }
    }
    Ok(None)
}

/// `PROGRAM Name`, `FUNCTION Name : TYPE`, … : a POU's first line.
fn pou_header(
    keyword: &str,
    name: &str,
    pou_type: &str,
    return_type: Option<String>,
) -> Result<String, String> {
    if pou_type == "function" {
        let rt = return_type.ok_or("a function without <returnType>")?;
        Ok(format!("{keyword} {name} : {rt}"))
    } else {
        Ok(format!("{keyword} {name}"))
    }
}

/// Appends a POU written in ST to `source`.
fn push_pou(source: &mut String, header: &str, declarations: &str, body: &str, end: &str) {
    source.push_str(header);
    source.push('\n');
    source.push_str(declarations);
    let body = body.trim_matches('\n');
    if !body.trim().is_empty() {
        source.push_str(body);
        source.push('\n');
    }
    source.push_str(end);
    source.push_str("\n\n");
}

/// Whether `declarations` declare `name` (a whole word before a colon).
fn declares(declarations: &str, name: &str) -> bool {
    declarations.lines().any(|l| {
        l.split(':')
            .next()
            .is_some_and(|names| names.split(',').any(|n| n.trim().eq_ignore_ascii_case(name)))
    })
}

/// Parses a task interval such as `T#20ms`, `T#1s`, `PT0.02S` into milliseconds.
fn parse_interval_ms(text: &str) -> Option<u64> {
    let t = text.trim().to_ascii_lowercase();
    if let Some(iso) = t.strip_prefix("pt") {
        let secs: f64 = iso.strip_suffix('s')?.parse().ok()?;
        return Some((secs * 1000.0).round() as u64).filter(|&m| m > 0);
    }
    let body = t.strip_prefix("t#").or_else(|| t.strip_prefix("time#"))?.replace('_', "");
    let (num, factor) = if let Some(n) = body.strip_suffix("ms") {
        (n, 1.0)
    } else if let Some(n) = body.strip_suffix('s') {
        (n, 1000.0)
    } else if let Some(n) = body.strip_suffix('m') {
        (n, 60000.0)
    } else {
        return None;
    };
    let v: f64 = num.parse().ok()?;
    Some((v * factor).round() as u64).filter(|&m| m > 0)
}

/// One interface section (`<inputVars retain=…>`) as an ST `VAR… END_VAR` block.
pub(crate) fn var_block(block: &Node, section: &str, _attrs: &str) -> Result<String, String> {
    let mut out = String::from(section);
    if block.attr("retain") == Some("true") {
        out.push_str(" RETAIN");
    }
    if block.attr("nonretain") == Some("true") {
        out.push_str(" NON_RETAIN");
    }
    if block.attr("constant") == Some("true") {
        out.push_str(" CONSTANT");
    }
    out.push('\n');
    for v in block.children_named("variable") {
        out.push_str("    ");
        out.push_str(&variable_text(v)?);
        out.push('\n');
    }
    out.push_str("END_VAR\n");
    Ok(out)
}

/// `name AT %IX0.0 : BOOL := FALSE; (* doc *)`.
fn variable_text(v: &Node) -> Result<String, String> {
    let name = v.attr("name").filter(|n| !n.is_empty()).ok_or("a <variable> without a name")?;
    let mut out = name.to_string();
    if let Some(addr) = v.attr("address").filter(|a| !a.trim().is_empty()) {
        out.push_str(" AT ");
        out.push_str(addr.trim());
    }
    let ty = v.child("type").ok_or_else(|| format!("variable {name} has no <type>"))?;
    out.push_str(" : ");
    out.push_str(&type_text(ty).map_err(|e| format!("variable {name}: {e}"))?);
    if let Some(init) = v.child("initialValue") {
        out.push_str(" := ");
        out.push_str(&value_text(init).map_err(|e| format!("variable {name}: {e}"))?);
    }
    out.push(';');
    if let Some(doc) = v.child("documentation") {
        let text = doc_text(doc);
        if !text.is_empty() {
            out.push_str(" (* ");
            out.push_str(&text);
            out.push_str(" *)");
        }
    }
    Ok(out)
}

/// A documentation element as one comment-safe line.
pub(crate) fn doc_text(doc: &Node) -> String {
    doc.deep_text().split_whitespace().collect::<Vec<_>>().join(" ").replace("*)", "* )")
}

const ELEMENTARY: &[&str] = &[
    "BOOL", "SINT", "INT", "DINT", "LINT", "USINT", "UINT", "UDINT", "ULINT", "REAL", "LREAL",
    "TIME", "DATE", "DT", "TOD", "BYTE", "WORD", "DWORD", "LWORD", "LTIME", "STRING", "WSTRING",
];

/// The ST text of the type held by a `<type>`/`<baseType>`/`<returnType>` wrapper.
pub(crate) fn type_text(wrapper: &Node) -> Result<String, String> {
    let t = wrapper.children.first().ok_or_else(|| format!("<{}> is empty", wrapper.name))?;
    type_node_text(t)
}

fn type_node_text(t: &Node) -> Result<String, String> {
    Ok(match t.name.as_str() {
        "derived" => {
            t.attr("name").filter(|n| !n.is_empty()).ok_or("<derived> without name")?.into()
        }
        "string" | "wstring" => {
            let kw = if t.name == "string" { "STRING" } else { "WSTRING" };
            match t.attr("length") {
                Some(l) if !l.is_empty() => format!("{kw}[{l}]"),
                _ => kw.into(),
            }
        }
        "array" => {
            let dims = t
                .children_named("dimension")
                .map(|d| match (d.attr("lower"), d.attr("upper")) {
                    (Some(l), Some(u)) => Ok(format!("{l}..{u}")),
                    _ => Err("an array <dimension> needs lower and upper".to_string()),
                })
                .collect::<Result<Vec<_>, _>>()?;
            if dims.is_empty() {
                return Err("an <array> without <dimension>".into());
            }
            let base = t.child("baseType").ok_or("an <array> without <baseType>")?;
            format!("ARRAY[{}] OF {}", dims.join(", "), type_text(base)?)
        }
        "subrangeSigned" | "subrangeUnsigned" => {
            let r = t.child("range").ok_or("a subrange without <range>")?;
            let (l, u) =
                r.attr("lower").zip(r.attr("upper")).ok_or("a <range> needs lower and upper")?;
            let base = t.child("baseType").ok_or("a subrange without <baseType>")?;
            format!("{}({l}..{u})", type_text(base)?)
        }
        "enum" => {
            let values = t.child("values").ok_or("an <enum> without <values>")?;
            let names = values
                .children_named("value")
                .map(|v| {
                    let n = v.attr("name").ok_or("an enum <value> without name")?;
                    Ok(match v.attr("value") {
                        Some(x) => format!("{n} := {x}"),
                        None => n.to_string(),
                    })
                })
                .collect::<Result<Vec<_>, String>>()?;
            if names.is_empty() {
                return Err("an <enum> without values".into());
            }
            format!("({})", names.join(", "))
        }
        "struct" => {
            let mut out = String::from("STRUCT\n");
            for v in t.children_named("variable") {
                out.push_str("        ");
                out.push_str(&variable_text(v)?);
                out.push('\n');
            }
            out.push_str("    END_STRUCT");
            out
        }
        "pointer" => return Err("pointer types are not supported".into()),
        other => {
            let upper = other.to_ascii_uppercase();
            if ELEMENTARY.contains(&upper.as_str()) || upper == "DATE_AND_TIME" {
                upper
            } else if upper == "TIME_OF_DAY" {
                "TOD".into()
            } else {
                return Err(format!("unsupported type <{other}>"));
            }
        }
    })
}

/// The ST text of an `<initialValue>` (or an array/struct `<value>`) wrapper.
pub(crate) fn value_text(wrapper: &Node) -> Result<String, String> {
    let v = wrapper
        .children
        .iter()
        .find(|c| c.name.ends_with("Value"))
        .ok_or_else(|| format!("<{}> holds no value", wrapper.name))?;
    match v.name.as_str() {
        "simpleValue" => Ok(v.attr("value").unwrap_or("").to_string()),
        "arrayValue" => {
            let items = v
                .children_named("value")
                .map(|item| {
                    let inner = value_text(item)?;
                    Ok(match item.attr("repetitionValue") {
                        Some(n) if inner.is_empty() => format!("{n}()"),
                        Some(n) => format!("{n}({inner})"),
                        None => inner,
                    })
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok(format!("[{}]", items.join(", ")))
        }
        "structValue" => {
            let items = v
                .children_named("value")
                .map(|item| {
                    let m = item.attr("member").ok_or("a struct <value> without member")?;
                    Ok(format!("{m} := {}", value_text(item)?))
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok(format!("({})", items.join(", ")))
        }
        other => Err(format!("unsupported initial value <{other}>")),
    }
}
