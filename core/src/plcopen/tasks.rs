//! Tasks and program instances between PLCopen XML and a CONFIGURATION.
//!
//! Import: a file's `<configuration>` whose tasks run more than one program instance
//! becomes an ST `CONFIGURATION` block (each `<resource>` a RESOURCE, each `<task>` a
//! TASK, each `<pouInstance>` a PROGRAM instance WITH its task), so every instance runs
//! under its task; with one instance the file's program simply runs, as before. Its
//! globals are written as top-level VAR_GLOBAL blocks by the import itself, and its
//! `<configVars>` read there become the VAR_CONFIG block.
//! Export: the source's CONFIGURATION becomes the file's configuration, resources, tasks
//! and instances, and its VAR_CONFIG entries `<configVariable>`s (TC6: the instance path,
//! the address, the type and the initial value).

use std::fmt::Write;

use super::decl_xml::{init_xml, type_xml, vars_xml};
use super::source_out::SourceOut;
use super::xml::{esc, Node};
use super::ImportNote;
use crate::syntax::ast::Configuration;

/// The CONFIGURATION text for the instances of `conf` whose type is one of `programs`
/// (the PROGRAM POUs the import kept), with the VAR_CONFIG entries `config_vars` (each
/// line with its element), and the clock tick (ms) that serves every task:
/// `None` when fewer than two instances would run. Instances of other types are noted in
/// `notes` and left out.
pub(super) fn configuration_text(
    conf: &Node,
    programs: &[String],
    config_vars: &[(String, &Node)],
    notes: &mut Vec<ImportNote>,
) -> Option<(SourceOut, u64)> {
    let known = |t: &str| programs.iter().any(|p| p.eq_ignore_ascii_case(t));
    let mut out = SourceOut::default();
    let mut instances = 0;
    let mut tick: u64 = 0;
    let cname = conf.attr("name").unwrap_or("config");
    out.push_from(&format!("CONFIGURATION {}\n", ident(cname)), conf);
    for res in conf.children_named("resource") {
        let rname = res.attr("name").unwrap_or("resource");
        out.push_from(&format!("    RESOURCE {} ON PLC\n", ident(rname)), res);
        for task in res.children_named("task") {
            let tname = task.attr("name").unwrap_or("task");
            let mut settings = Vec::new();
            if let Some(ms) = task.attr("interval").and_then(parse_interval_ms) {
                settings.push(format!("INTERVAL := T#{ms}ms"));
                tick = gcd(tick, ms);
            }
            if let Some(single) = task.attr("single").filter(|s| !s.trim().is_empty()) {
                settings.push(format!("SINGLE := {}", single.trim()));
            }
            let priority = task.attr("priority").and_then(|p| p.trim().parse::<u32>().ok());
            settings.push(format!("PRIORITY := {}", priority.unwrap_or(0)));
            out.push_from(
                &format!("        TASK {} ({});\n", ident(tname), settings.join(", ")),
                task,
            );
            for inst in task.children_named("pouInstance") {
                instances += instance(&mut out, inst, Some(tname), &known, notes);
            }
        }
        for inst in res.children_named("pouInstance") {
            instances += instance(&mut out, inst, None, &known, notes);
        }
        out.push("    END_RESOURCE\n", None);
    }
    if !config_vars.is_empty() {
        out.push("    VAR_CONFIG\n", None);
        for (line, node) in config_vars {
            out.push_from(line, node);
        }
        out.push("    END_VAR\n", None);
    }
    out.push("END_CONFIGURATION\n", None);
    if instances < 2 && !config_vars.is_empty() {
        notes.push(ImportNote::on(conf, crate::msg!(PlcopenVarConfigNotApplied, name = cname)));
    }
    (instances > 1).then_some((out, tick))
}

/// Writes one `PROGRAM name [WITH task] : Type;` line; 1 when written, 0 when its type was
/// not kept.
fn instance(
    out: &mut SourceOut,
    inst: &Node,
    task: Option<&str>,
    known: &dyn Fn(&str) -> bool,
    notes: &mut Vec<ImportNote>,
) -> usize {
    let name = inst.attr("name").unwrap_or("instance");
    let ty = inst.attr("typeName").unwrap_or("");
    if !known(ty) {
        notes.push(ImportNote::on(inst, crate::msg!(PlcopenInstanceNotRun, name = name, ty = ty)));
        return 0;
    }
    let with = task.map(|t| format!(" WITH {}", ident(t))).unwrap_or_default();
    out.push_from(&format!("        PROGRAM {}{with} : {};\n", ident(name), ident(ty)), inst);
    1
}

/// A name from the file as an ST identifier (characters that cannot be in one become `_`).
pub(super) fn ident(name: &str) -> String {
    let s: String =
        name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    if s.starts_with(|c: char| c.is_ascii_digit()) || s.is_empty() {
        format!("_{s}")
    } else {
        s
    }
}

fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// The `<configuration>` element of `config` (parsed from `src`), indented for the
/// export's `<configurations>`; `extra_globals` are the source's top-level VAR_GLOBAL
/// blocks, already as `<globalVars>`, written in the configuration.
pub(super) fn configuration_xml(config: &Configuration, src: &str, extra_globals: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "      <configuration name=\"{}\">", esc(&config.name.name));
    for res in &config.resources {
        let _ = writeln!(out, "        <resource name=\"{}\">", esc(&res.name.name));
        for task in &res.tasks {
            let text = |e: &Option<crate::syntax::ast::Expr>| {
                e.as_ref().and_then(|e| src.get(e.span.start as usize..e.span.end as usize))
            };
            let _ = write!(out, "          <task name=\"{}\"", esc(&task.name.name));
            if let Some(s) = text(&task.single) {
                let _ = write!(out, " single=\"{}\"", esc(s.trim()));
            }
            if let Some(i) = text(&task.interval) {
                let _ = write!(out, " interval=\"{}\"", esc(i.trim()));
            }
            let _ =
                writeln!(out, " priority=\"{}\">", esc(text(&task.priority).unwrap_or("0").trim()));
            for p in res.programs.iter().filter(|p| {
                p.task.as_ref().is_some_and(|t| t.name.eq_ignore_ascii_case(&task.name.name))
            }) {
                let _ = writeln!(
                    out,
                    "            <pouInstance name=\"{}\" typeName=\"{}\"/>",
                    esc(&p.name.name),
                    esc(&p.type_name.name)
                );
            }
            out.push_str("          </task>\n");
        }
        for g in &res.globals {
            out.push_str(&vars_xml(g, src, "globalVars", "          "));
        }
        for p in res.programs.iter().filter(|p| p.task.is_none()) {
            let _ = writeln!(
                out,
                "          <pouInstance name=\"{}\" typeName=\"{}\"/>",
                esc(&p.name.name),
                esc(&p.type_name.name)
            );
        }
        out.push_str("        </resource>\n");
    }
    out.push_str(extra_globals);
    for g in &config.globals {
        out.push_str(&vars_xml(g, src, "globalVars", "        "));
    }
    if !config.var_config.is_empty() {
        out.push_str("        <configVars>\n");
        for v in &config.var_config {
            let path: Vec<&str> = v.path.iter().map(|i| i.name.as_str()).collect();
            let _ = write!(
                out,
                "          <configVariable instancePathAndName=\"{}\"",
                esc(&path.join("."))
            );
            if let Some(loc) = &v.location {
                let _ = write!(out, " address=\"{}\"", esc(&loc.text));
            }
            let _ = writeln!(out, ">\n            <type>{}</type>", type_xml(&v.ty, src));
            if let Some(init) = &v.init {
                let _ = writeln!(
                    out,
                    "            <initialValue>{}</initialValue>",
                    init_xml(init, src)
                );
            }
            out.push_str("          </configVariable>\n");
        }
        out.push_str("        </configVars>\n");
    }
    out.push_str("      </configuration>\n");
    out
}

/// Parses a task interval such as `T#20ms`, `T#1s`, `PT0.02S` into milliseconds.
pub(super) fn parse_interval_ms(text: &str) -> Option<u64> {
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
