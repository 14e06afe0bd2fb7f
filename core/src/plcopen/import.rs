//! PLCopen XML → project: interfaces, data types and ST bodies as ST text; LD bodies via
//! [`super::ld_import`].

use super::source_out::SourceOut;
use super::xml::{self, Node};
use super::{Import, ImportError, ImportNote, SkippedPou};
use crate::diagnostics::Said;
use crate::ladder::{LadderPou, LadderPouKind};
use crate::network::{NetworkLanguage, NetworkPou, NetworkPouKind};
use crate::project::{Project, Settings, SCHEMA_VERSION};

/// Imports a PLCopen XML (TC6 0201) document.
pub fn import(xml_text: &str) -> Result<Import, ImportError> {
    let root = xml::parse(xml_text).map_err(ImportError::Xml)?;
    if root.name != "project" {
        return Err(ImportError::NotPlcopen(crate::msg!(PlcopenRootNotProject, name = &root.name)));
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
    let mut source = SourceOut::default();

    // Data types.
    let mut type_lines = Vec::new();
    if let Some(dts) = types.and_then(|t| t.child("dataTypes")) {
        for dt in dts.children_named("dataType") {
            let tname = dt.attr("name").unwrap_or("").to_string();
            let err = |message: Said| ImportError::DataType { name: tname.clone(), message };
            if tname.is_empty() {
                return Err(err(crate::msg!(PlcopenDataTypeNoName)));
            }
            let base = dt.child("baseType").ok_or_else(|| err(crate::msg!(PlcopenNoBaseType)))?;
            let ty = type_text(base).map_err(err)?;
            let init = match dt.child("initialValue") {
                Some(v) => format!(" := {}", value_text(v).map_err(err)?),
                None => String::new(),
            };
            type_lines.push((format!("    {tname} : {ty}{init};\n"), dt));
        }
    }
    if !type_lines.is_empty() {
        source.push("TYPE\n", None);
        for (l, dt) in type_lines {
            source.push_from(&l, dt);
        }
        source.push("END_TYPE\n\n", None);
    }

    // Globals of configurations and resources.
    let mut settings = Settings::default();
    let mut globals = SourceOut::default();
    let confs = root.child("instances").and_then(|i| i.child("configurations"));
    if let Some(confs) = confs {
        for conf in confs.children_named("configuration") {
            let cname = conf.attr("name").unwrap_or("config");
            for g in conf.children_named("globalVars") {
                globals.append(var_block(g, "VAR_GLOBAL", &mut warnings).map_err(|message| {
                    ImportError::Globals {
                        element: "configuration",
                        name: cname.to_string(),
                        message,
                    }
                })?);
            }
            for res in conf.children_named("resource") {
                let rname = res.attr("name").unwrap_or("resource");
                for g in res.children_named("globalVars") {
                    globals.append(var_block(g, "VAR_GLOBAL", &mut warnings).map_err(
                        |message| ImportError::Globals {
                            element: "resource",
                            name: rname.to_string(),
                            message,
                        },
                    )?);
                }
                if let Some(ms) = res
                    .children_named("task")
                    .find_map(|t| t.attr("interval").and_then(super::tasks::parse_interval_ms))
                    .filter(|&ms| crate::limits::cycle_ns(ms).is_ok())
                {
                    settings.cycle_ms = ms;
                }
            }
        }
    }
    if !globals.text.is_empty() {
        source.append(globals);
        source.push("\n", None);
    }

    // POUs: ST texts and LD declarations first, so LD bodies know every block type.
    let mut ladder = Vec::new();
    let mut networks = Vec::new();
    let mut places = Vec::new();
    let mut declaration_lines = Vec::new();
    let mut bodies = Vec::new();
    if let Some(pous) = types.and_then(|t| t.child("pous")) {
        for pou in pous.children_named("pou") {
            let mut out = PouOut {
                source: &mut source,
                ladder: &mut ladder,
                warnings: &mut warnings,
                skipped: &mut skipped,
                networks: &mut networks,
                places: &mut places,
                declarations: &mut declaration_lines,
            };
            if let Some(body) = import_pou(pou, &mut out)? {
                bodies.push(body);
            }
        }
    }
    let mut project = Project {
        schema: SCHEMA_VERSION,
        name,
        source: source.text.clone(),
        settings,
        ladder,
        petri: Vec::new(),
        networks,
        scene: None,
    };
    trainer_settings(&root, &mut project);
    let catalog = project.catalog();
    // LD networks that do not fit the rung grid stay networks, run by power flow.
    let mut off_grid = Vec::new();
    for (k, (pou_node, body)) in bodies.into_iter().enumerate() {
        let lp = &mut project.ladder[k];
        // The grid's notes count only if the network stays a grid.
        let mut grid_notes = Vec::new();
        let laid_out = super::ld_import::import_ld(
            body,
            &lp.name,
            &catalog,
            &lp.declarations,
            &mut grid_notes,
        );
        // Why the network is not a grid: it does not lay out, or it breaks a rule of the grid
        // that the tool which wrote it does not have (a coil passes its power on, a coil on
        // the rail is always on, an element may lead nowhere).
        let off = match &laid_out {
            Err(ImportError::Element { local_id, message, .. }) => {
                Some(crate::msg!(NetElementSays, element = local_id, message = message))
            }
            Err(other) => Some(other.said()),
            Ok(ld) => {
                let grid = LadderPou { rungs: ld.rungs.clone(), ..lp.clone() };
                crate::ladder::validate_with(&grid, &catalog)
                    .into_iter()
                    .find(|d| GRID_ONLY_RULES.contains(&d.code))
                    .map(|d| {
                        let message = Said { message: d.msg, english: d.message };
                        crate::msg!(
                            PlcopenGridRule,
                            code = d.code.to_string(),
                            rung = d.rung + 1,
                            row = d.row + 1,
                            column = d.column + 1,
                            message = message
                        )
                    })
            }
        };
        if let Some(why) = off {
            let kind = match lp.kind {
                LadderPouKind::Program => NetworkPouKind::Program,
                LadderPouKind::FunctionBlock => NetworkPouKind::FunctionBlock,
            };
            let mut declarations = SourceOut::default();
            declarations.push(&lp.declarations, None);
            let name = lp.name.clone();
            match keep_network(
                &name,
                kind,
                None,
                NetworkLanguage::Ld,
                declarations,
                (body, pou_node),
            ) {
                Ok((net, _, left_out)) => {
                    warnings.extend(left_out);
                    warnings.push(ImportNote::on(
                        body,
                        crate::msg!(PlcopenLdOffGrid, pou = &name, why = why),
                    ));
                    off_grid.push((k, net));
                    continue;
                }
                // Neither fits: the grid's problem is reported, with the network's.
                Err(lowering) => {
                    if let Err(ImportError::Element { pou, local_id, message }) = laid_out {
                        let message = crate::msg!(
                            PlcopenNotByPowerFlowEither,
                            message = message,
                            lowering = lowering.said()
                        );
                        return Err(ImportError::Element { pou, local_id, message });
                    }
                }
            }
        }
        let ld = laid_out?;
        warnings.extend(grid_notes);
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
            warnings.push(ImportNote::on(
                pou_node,
                crate::msg!(PlcopenDataWireVariables, pou = &lp.name),
            ));
        }
    }
    // Removed from the back (indices stay valid), added in the file's order.
    for (k, _) in off_grid.iter().rev() {
        project.ladder.remove(*k);
    }
    for (_, net) in off_grid {
        places.extend(network_places(&net));
        project.networks.push(net);
    }
    // Several program instances: a CONFIGURATION runs each under its task.
    let programs: Vec<String> = types
        .and_then(|t| t.child("pous"))
        .into_iter()
        .flat_map(|p| p.children_named("pou"))
        .filter(|p| p.attr("pouType") == Some("program"))
        .filter_map(|p| p.attr("name"))
        .filter(|n| !skipped.iter().any(|s| s.name.eq_ignore_ascii_case(n)))
        .map(str::to_string)
        .collect();
    if let Some(conf) = confs.and_then(|c| c.children_named("configuration").next()) {
        let config_vars = config_var_lines(conf, &mut warnings);
        if let Some((text, tick)) =
            super::tasks::configuration_text(conf, &programs, &config_vars, &mut warnings)
        {
            source.push("\n", None);
            source.append(text);
            if tick > 0
                && crate::limits::cycle_ns(tick).is_ok()
                && project.settings.program.is_none()
            {
                project.settings.cycle_ms = tick;
            }
        }
    }
    project.source = source.text;
    let file_map =
        crate::build::FileMap { places, lines: source.lines, declarations: declaration_lines };
    Ok(Import { project, warnings, skipped, file_map })
}

/// The VAR_CONFIG entries of the `<configVariable>`s of `conf`, each with its element.
/// An entry the trainer cannot read is noted and left out.
fn config_var_lines<'n>(conf: &'n Node, notes: &mut Vec<ImportNote>) -> Vec<(String, &'n Node)> {
    let mut out = Vec::new();
    for v in conf.children_named("configVars").flat_map(|c| c.children_named("configVariable")) {
        match config_var_text(v) {
            Ok(line) => out.push((line, v)),
            Err(why) => {
                let path = v.attr("instancePathAndName").unwrap_or("");
                notes.push(ImportNote::on(
                    v,
                    crate::msg!(PlcopenVarConfigLeftOut, path = path, why = why),
                ));
            }
        }
    }
    out
}

/// One `<configVariable>` as a VAR_CONFIG entry: `Line.V1.Open AT %QX1.0 : BOOL := TRUE;`.
fn config_var_text(v: &Node) -> Result<String, Said> {
    let path = v
        .attr("instancePathAndName")
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .ok_or_else(|| crate::msg!(PlcopenNoInstancePath))?;
    let path: Vec<String> = path.split('.').map(|n| super::tasks::ident(n.trim())).collect();
    let at = match v.attr("address").map(str::trim).filter(|a| !a.is_empty()) {
        None => String::new(),
        Some(a) => match a.strip_prefix('%') {
            Some(rest) if rest.chars().all(|c| c.is_ascii_alphanumeric() || c == '.') => {
                format!(" AT {a}")
            }
            _ => return Err(crate::msg!(PlcopenIncompleteAddress, address = a)),
        },
    };
    let ty = type_text(v.child("type").ok_or_else(|| crate::msg!(PlcopenNoType))?)?;
    let init = match v.child("initialValue") {
        Some(w) => format!(" := {}", value_text(w)?),
        None => String::new(),
    };
    Ok(format!("        {}{at} : {ty}{init};\n", path.join(".")))
}

/// Leaves the POU `name` out of the import, with a note at its body saying why.
fn skip_pou(out: &mut PouOut<'_>, body: &Node, name: String, keyword: &str, reason: Said) {
    out.warnings
        .push(ImportNote::on(body, crate::msg!(PlcopenPouSkipped, pou = &name, reason = &reason)));
    out.skipped.push(SkippedPou {
        name,
        kind: keyword.to_string(),
        reason: reason.english.clone(),
        reason_said: reason,
    });
}

/// What kind of network POU a `pouType` makes.
fn network_kind(pou_type: &str) -> NetworkPouKind {
    match pou_type {
        "function" => NetworkPouKind::Function,
        "functionBlock" => NetworkPouKind::FunctionBlock,
        _ => NetworkPouKind::Program,
    }
}

/// A network POU read from a file, the places in the file of its declaration lines, and
/// the notes on elements left out.
type KeptNetwork = (NetworkPou, Vec<Option<crate::build::SourceLine>>, Vec<ImportNote>);

/// The network POU of an LD or FBD `body`, checked to run (lowered once), with the places
/// in the file of its declaration lines and the notes on elements left out.
fn keep_network(
    name: &str,
    kind: NetworkPouKind,
    return_type: Option<String>,
    language: NetworkLanguage,
    declarations: SourceOut,
    (body, pou): (&Node, &Node),
) -> Result<KeptNetwork, ImportError> {
    let (elements, mut left_out) = super::ld_import::read::read_network(body, name)?;
    let err = |message: Said| ImportError::Pou { pou: name.to_string(), message };
    let (mut actions, mut transitions) = (Vec::new(), Vec::new());
    if language == NetworkLanguage::Sfc {
        actions =
            super::sfc_read::named_bodies(pou, "actions", name, &mut left_out).map_err(err)?;
        transitions =
            super::sfc_read::named_bodies(pou, "transitions", name, &mut left_out).map_err(err)?;
    }
    let net = NetworkPou {
        name: name.to_string(),
        kind,
        return_type,
        language,
        declarations: declarations.text,
        elements,
        actions,
        transitions,
    };
    net.to_st().map_err(|e| element_error(name, e))?;
    if language == NetworkLanguage::Sfc {
        // What the chart leaves out (a transition wired to no step), at its element.
        let chart = crate::network::chart::chart_text(&net).map_err(|e| element_error(name, e))?;
        for (id, message) in chart.notes {
            let at = net.elements.iter().find(|e| e.id == id).map_or((0, 0), |e| e.at);
            left_out.push(ImportNote::at(at.0, at.1, message));
        }
    }
    Ok((net, declarations.lines, left_out))
}

/// A network error as an import error of POU `pou`.
fn element_error(pou: &str, e: crate::network::NetError) -> ImportError {
    let message = e.said();
    ImportError::Element { pou: pou.to_string(), local_id: e.element, message }
}

/// Adds a network POU to the project being imported.
fn add_network(
    out: &mut PouOut<'_>,
    net: NetworkPou,
    declarations: Vec<Option<crate::build::SourceLine>>,
) {
    out.declarations.push((net.name.clone(), declarations));
    out.places.extend(network_places(&net));
    out.networks.push(net);
}

/// Where each element of a network POU is in the file.
fn network_places(net: &NetworkPou) -> impl Iterator<Item = crate::build::FilePlace> + '_ {
    net.elements.iter().filter(|e| !e.id.is_empty()).map(|e| crate::build::FilePlace {
        site: crate::build::Site::Network { pou: net.name.clone(), element: Some(e.id.clone()) },
        line: e.at.0,
        column: e.at.1,
    })
}

/// Ladder rules of the trainer's rung grid that OpenPLC and Beremiz do not have: a network
/// an imported file breaks them with runs by power flow instead.
const GRID_ONLY_RULES: &[crate::diagnostics::Code] = &[
    crate::diagnostics::Code::LadderOpenCircuit,
    crate::diagnostics::Code::LadderShortCircuit,
    crate::diagnostics::Code::LadderAfterCoil,
    crate::diagnostics::Code::LadderBadPowerPin,
];

/// Where [`import_pou`] puts what it reads.
struct PouOut<'o> {
    source: &'o mut SourceOut,
    ladder: &'o mut Vec<LadderPou>,
    warnings: &'o mut Vec<ImportNote>,
    skipped: &'o mut Vec<SkippedPou>,
    networks: &'o mut Vec<NetworkPou>,
    /// Where the elements of network POUs are in the file.
    places: &'o mut Vec<crate::build::FilePlace>,
    /// Where the declaration lines of ladder and network POUs came from.
    declarations: &'o mut Vec<(String, Vec<Option<crate::build::SourceLine>>)>,
}

/// Imports one POU: ST POUs into `source`, LD POUs into `ladder` with no rungs yet (the POU
/// and its `<LD>` body are returned, to be laid out once every POU is known).
fn import_pou<'a>(
    pou: &'a Node,
    out: &mut PouOut<'_>,
) -> Result<Option<(&'a Node, &'a Node)>, ImportError> {
    let (source, ladder, warnings) = (&mut *out.source, &mut *out.ladder, &mut *out.warnings);
    let name = pou.attr("name").unwrap_or("").to_string();
    let err = |message: Said| ImportError::Pou { pou: name.clone(), message };
    if name.is_empty() {
        return Err(err(crate::msg!(PlcopenNoName)));
    }
    let pou_type = pou.attr("pouType").unwrap_or("program");
    let (keyword, end) = match pou_type {
        "program" => ("PROGRAM", "END_PROGRAM"),
        "functionBlock" => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        "function" => ("FUNCTION", "END_FUNCTION"),
        other => {
            return Err(err(crate::msg!(PlcopenUnknownPouType, pou_type = format!("{other:?}"))))
        }
    };
    let mut declarations = SourceOut::default();
    let mut return_type = None;
    if let Some(iface) = pou.child("interface") {
        for block in &iface.children {
            let section = match block.name.as_str() {
                "returnType" => {
                    return_type = Some(type_text(block).map_err(err)?);
                    continue;
                }
                "inputVars" => "VAR_INPUT",
                "outputVars" => "VAR_OUTPUT",
                "inOutVars" => "VAR_IN_OUT",
                "localVars" => "VAR",
                "tempVars" => "VAR_TEMP",
                "externalVars" => "VAR_EXTERNAL",
                "globalVars" => "VAR_GLOBAL",
                "documentation" | "addData" => continue,
                other => {
                    warnings.push(ImportNote::on(
                        block,
                        crate::msg!(PlcopenInterfaceSectionSkipped, pou = &name, section = other),
                    ));
                    continue;
                }
            };
            declarations.append(var_block(block, section, warnings).map_err(err)?);
        }
    }
    let body = pou.child("body").ok_or_else(|| err(crate::msg!(PlcopenNoBody)))?;
    let lang = body
        .children
        .iter()
        .find(|c| c.name != "documentation" && c.name != "addData")
        .ok_or_else(|| err(crate::msg!(PlcopenEmptyBody)))?;
    if lang.name != "SFC"
        && (pou.child("actions").is_some_and(|a| !a.children.is_empty())
            || pou.child("transitions").is_some_and(|a| !a.children.is_empty()))
    {
        warnings
            .push(ImportNote::on(pou, crate::msg!(PlcopenActionsTransitionsSkipped, pou = &name)));
    }
    match lang.name.as_str() {
        // An IL body is text too: the parser recognises IL by its first line.
        "ST" | "IL" => {
            let header = pou_header(keyword, &name, pou_type, return_type).map_err(err)?;
            push_pou(source, (&header, pou), declarations, st_body(lang), end);
        }
        // FBD and SFC bodies, and LD functions (a function has no rung grid), are kept as
        // drawn.
        "FBD" | "SFC" | "LD" if lang.name != "LD" || pou_type == "function" => {
            let language = match lang.name.as_str() {
                "FBD" => NetworkLanguage::Fbd,
                "SFC" => NetworkLanguage::Sfc,
                _ => NetworkLanguage::Ld,
            };
            let kind = network_kind(pou_type);
            let body = (lang, pou);
            match keep_network(&name, kind, return_type, language, declarations, body) {
                Ok((net, lines, left_out)) => {
                    out.warnings.extend(left_out);
                    add_network(out, net, lines)
                }
                Err(e) => {
                    let reason = crate::msg!(
                        PlcopenBodyCannotBeImported,
                        language = &lang.name,
                        error = e.said()
                    );
                    skip_pou(out, lang, name, keyword, reason);
                }
            }
        }
        "LD" => {
            let kind = if pou_type == "program" {
                LadderPouKind::Program
            } else {
                LadderPouKind::FunctionBlock
            };
            out.declarations.push((name.clone(), declarations.lines.clone()));
            ladder.push(LadderPou {
                name,
                kind,
                declarations: declarations.text,
                rungs: Vec::new(),
            });
            return Ok(Some((pou, lang)));
        }
        other => {
            let reason = crate::msg!(PlcopenBodiesNotSupported, language = other);
            skip_pou(out, lang, name, keyword, reason);
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
) -> Result<String, Said> {
    if pou_type == "function" {
        let rt = return_type.ok_or_else(|| crate::msg!(PlcopenFunctionWithoutReturnType))?;
        Ok(format!("{keyword} {name} : {rt}"))
    } else {
        Ok(format!("{keyword} {name}"))
    }
}

/// Appends a POU written in ST to `source`: its header (written from the `<pou>` element),
/// declarations and body.
fn push_pou(
    source: &mut SourceOut,
    (header, pou): (&str, &Node),
    declarations: SourceOut,
    body: SourceOut,
    end: &str,
) {
    source.push_from(&format!("{header}\n"), pou);
    source.append(declarations);
    if !body.text.trim().is_empty() {
        source.append(body);
        if !source.text.ends_with('\n') {
            source.push("\n", None);
        }
    }
    source.push(&format!("{end}\n\n"), None);
}

/// The text of an ST body, tracked to its place in the file when one element holds it all
/// (the usual `<xhtml:p><![CDATA[…]]></xhtml:p>`).
fn st_body(lang: &Node) -> SourceOut {
    let mut holders = Vec::new();
    text_holders(lang, &mut holders);
    let mut out = SourceOut::default();
    match holders.as_slice() {
        [holder] => {
            let (line, column) = holder.text_at.unwrap_or((holder.line, holder.column));
            out.push_verbatim(&holder.text.replace("\r\n", "\n"), line, column);
        }
        _ => out.push_from(&lang.deep_text().replace("\r\n", "\n"), lang),
    }
    out
}

/// The elements of `node`'s tree that hold text other than white space.
fn text_holders<'a>(node: &'a Node, out: &mut Vec<&'a Node>) {
    if !node.text.trim().is_empty() {
        out.push(node);
    }
    for c in &node.children {
        text_holders(c, out);
    }
}

/// One interface section (`<inputVars retain=…>`) as an ST `VAR… END_VAR` block, each
/// variable's line written from its `<variable>`; what was changed on the way is noted in
/// `notes`.
pub(crate) fn var_block(
    block: &Node,
    section: &str,
    notes: &mut Vec<ImportNote>,
) -> Result<SourceOut, Said> {
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
    let mut text = SourceOut::default();
    text.push_from(&out, block);
    for v in block.children_named("variable") {
        text.push_from(&format!("    {}\n", variable_text(v, notes)?), v);
    }
    text.push("END_VAR\n", None);
    Ok(text)
}

/// `name AT %IX0.0 : BOOL := FALSE; (* doc *)`. A TIME initial value written as a whole
/// number is read as milliseconds, as matiec reads it, with a note in `notes`.
fn variable_text(v: &Node, notes: &mut Vec<ImportNote>) -> Result<String, Said> {
    let name = v
        .attr("name")
        .filter(|n| !n.is_empty())
        .ok_or_else(|| crate::msg!(PlcopenVariableWithoutName))?;
    let mut out = name.to_string();
    if let Some(addr) = v.attr("address").filter(|a| !a.trim().is_empty()) {
        out.push_str(" AT ");
        out.push_str(addr.trim());
    }
    let ty = v.child("type").ok_or_else(|| crate::msg!(PlcopenVariableNoType, name = name))?;
    out.push_str(" : ");
    let in_variable = |e: Said| crate::msg!(PlcopenVariableError, name = name, message = e);
    let type_name = type_text(ty).map_err(in_variable)?;
    out.push_str(&type_name);
    if let Some(init) = v.child("initialValue") {
        let mut value = value_text(init).map_err(in_variable)?;
        let is_duration = matches!(type_name.as_str(), "TIME" | "LTIME");
        if is_duration && !value.is_empty() && value.bytes().all(|b| b.is_ascii_digit()) {
            notes.push(ImportNote::on(
                init,
                crate::msg!(PlcopenTimeAsMs, name = name, value = &value),
            ));
            value = format!("T#{value}ms");
        }
        out.push_str(" := ");
        out.push_str(&value);
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
pub(crate) fn type_text(wrapper: &Node) -> Result<String, Said> {
    let t = wrapper
        .children
        .first()
        .ok_or_else(|| crate::msg!(PlcopenWrapperEmpty, name = &wrapper.name))?;
    type_node_text(t)
}

fn type_node_text(t: &Node) -> Result<String, Said> {
    // The part of `t` named `name`, or `missing`.
    let part = |name: &str, missing: fn() -> Said| t.child(name).ok_or_else(missing);
    Ok(match t.name.as_str() {
        "derived" => t
            .attr("name")
            .filter(|n| !n.is_empty())
            .ok_or_else(|| crate::msg!(PlcopenDerivedWithoutName))?
            .into(),
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
                    _ => Err(crate::msg!(PlcopenDimensionNeedsBounds)),
                })
                .collect::<Result<Vec<_>, _>>()?;
            if dims.is_empty() {
                return Err(crate::msg!(PlcopenArrayWithoutDimension));
            }
            let base = part("baseType", || crate::msg!(PlcopenArrayWithoutBaseType))?;
            format!("ARRAY[{}] OF {}", dims.join(", "), type_text(base)?)
        }
        "subrangeSigned" | "subrangeUnsigned" => {
            let r = part("range", || crate::msg!(PlcopenSubrangeWithoutRange))?;
            let (l, u) = r
                .attr("lower")
                .zip(r.attr("upper"))
                .ok_or_else(|| crate::msg!(PlcopenRangeNeedsBounds))?;
            let base = part("baseType", || crate::msg!(PlcopenSubrangeWithoutBaseType))?;
            format!("{}({l}..{u})", type_text(base)?)
        }
        "enum" => {
            let values = part("values", || crate::msg!(PlcopenEnumWithoutValuesElement))?;
            let names = values
                .children_named("value")
                .map(|v| {
                    let n =
                        v.attr("name").ok_or_else(|| crate::msg!(PlcopenEnumValueWithoutName))?;
                    Ok(match v.attr("value") {
                        Some(x) => format!("{n} := {x}"),
                        None => n.to_string(),
                    })
                })
                .collect::<Result<Vec<_>, Said>>()?;
            if names.is_empty() {
                return Err(crate::msg!(PlcopenEnumWithoutValues));
            }
            format!("({})", names.join(", "))
        }
        "struct" => {
            let mut out = String::from("STRUCT\n");
            for v in t.children_named("variable") {
                out.push_str("        ");
                // A member's value is converted like a variable's; the note has no place
                // to go from inside a type.
                out.push_str(&variable_text(v, &mut Vec::new())?);
                out.push('\n');
            }
            out.push_str("    END_STRUCT");
            out
        }
        // TC6 XML's `pointer` is edition 3's REF_TO.
        "pointer" => {
            let base = part("baseType", || crate::msg!(PlcopenPointerWithoutBaseType))?;
            format!("REF_TO {}", type_text(base)?)
        }
        other => {
            let upper = other.to_ascii_uppercase();
            if ELEMENTARY.contains(&upper.as_str()) || upper == "DATE_AND_TIME" {
                upper
            } else if upper == "TIME_OF_DAY" {
                "TOD".into()
            } else {
                return Err(crate::msg!(PlcopenUnsupportedType, name = other));
            }
        }
    })
}

/// The ST text of an `<initialValue>` (or an array/struct `<value>`) wrapper.
pub(crate) fn value_text(wrapper: &Node) -> Result<String, Said> {
    let v = wrapper
        .children
        .iter()
        .find(|c| c.name.ends_with("Value"))
        .ok_or_else(|| crate::msg!(PlcopenHoldsNoValue, name = &wrapper.name))?;
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
                .collect::<Result<Vec<_>, Said>>()?;
            Ok(format!("[{}]", items.join(", ")))
        }
        "structValue" => {
            let items = v
                .children_named("value")
                .map(|item| {
                    let m = item
                        .attr("member")
                        .ok_or_else(|| crate::msg!(PlcopenStructValueWithoutMember))?;
                    Ok(format!("{m} := {}", value_text(item)?))
                })
                .collect::<Result<Vec<_>, Said>>()?;
            Ok(format!("({})", items.join(", ")))
        }
        other => Err(crate::msg!(PlcopenUnsupportedInitialValue, name = other)),
    }
}

/// The `addData` name under which the trainer keeps what PLCopen has no place for.
pub(crate) const TRAINER_DATA: &str = "urn:plc-trainer:settings";

/// Reads the trainer's own settings from a file it exported (the PROGRAM chosen to run, the
/// plant, the scene): other tools discard this `addData`, the trainer takes it back.
fn trainer_settings(root: &super::xml::Node, project: &mut Project) {
    let Some(trainer) = root
        .child("addData")
        .into_iter()
        .flat_map(|a| a.children_named("data"))
        .find(|d| d.attr("name") == Some(TRAINER_DATA))
        .and_then(|d| d.child("trainer"))
    else {
        return;
    };
    project.settings.program = trainer.attr("program").map(str::to_string);
    project.settings.plant = trainer.attr("plant").map(str::to_string);
    project.scene =
        trainer.child("scene").and_then(|s| serde_json::from_str(s.deep_text().trim()).ok());
}
