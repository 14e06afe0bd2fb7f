#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Every PLCopen XML file the trainer exports is checked against the *structure* of the TC6
//! XML schema, version 2.01 (`tc6_0201`). The XSD is not in the repository (and there is no
//! network to fetch it), so the rules below are the schema's, written out by hand for the
//! elements the exporter writes.
//!
//! Checked, for every element the exporter writes (project, headers, coordinate info, data
//! types, POUs and their interfaces and variables, ST, LD and FBD bodies, rails, contacts, coils,
//! blocks and their pin lists, in/out variables, labels, jumps, returns, comments,
//! connection points and connections, configurations, resources, tasks, POU instances,
//! configuration variables):
//! - the children that may appear, in the order the schema's `xsd:sequence` fixes, and how
//!   often (`minOccurs` / `maxOccurs`); free-order `xsd:choice` lists (LD body objects,
//!   interface variable lists) as sets;
//! - the required attributes, and the values of enumerated ones (`pouType`, `edge`,
//!   `storage`, booleans), and numbers where the schema has `xsd:decimal` /
//!   `xsd:unsignedLong` (positions, `localId`, `refLocalId`);
//! - the default namespace `http://www.plcopen.org/xml/tc6_0201`;
//! - identity: `localId`s unique within a body, every `refLocalId` naming an element of the
//!   same body, a `formalParameter` on a connection from a block naming one of its outputs,
//!   every `pouInstance` naming a POU of the file.
//!
//! SFC bodies too: steps, transitions and their conditions, divergences and convergences,
//! jumps, action blocks and their actions, and the POU's named actions and transitions.
//!
//! Not checked: the text inside `xhtml:p` and `expression`/`variable` (ST syntax is the
//! importer's business), `addData` and `documentation` contents, element kinds the exporter
//! never writes (IL, macro steps, access paths), and the `xsd:ID` / `globalId` machinery.

use std::collections::{HashMap, HashSet};

use plc_core::plcopen::{export, import, load};
use plc_core::project::Project;
use quick_xml::events::Event;
use quick_xml::Reader;

#[derive(Debug, Default)]
struct Node {
    name: String,
    attrs: Vec<(String, String)>,
    children: Vec<Node>,
    ns: Option<String>,
}

impl Node {
    fn attr(&self, k: &str) -> Option<&str> {
        self.attrs.iter().find(|(n, _)| n == k).map(|(_, v)| v.as_str())
    }
}

fn parse(xml: &str) -> Node {
    let mut reader = Reader::from_str(xml);
    let mut stack: Vec<Node> = Vec::new();
    let mut root = None;
    let start = |e: &quick_xml::events::BytesStart<'_>| {
        let name = e.local_name().as_ref().to_string();
        let mut node = Node { name, ..Node::default() };
        for a in e.attributes() {
            let a = a.unwrap();
            let key = a.key.as_ref().to_string();
            let value =
                a.normalized_value(quick_xml::XmlVersion::Implicit1_0).unwrap().into_owned();
            if key == "xmlns" {
                node.ns = Some(value.clone());
            }
            let local = key.rsplit(':').next().unwrap_or(&key).to_string();
            if !key.starts_with("xmlns") {
                node.attrs.push((local, value));
            }
        }
        node
    };
    loop {
        match reader.read_event().unwrap() {
            Event::Start(e) => stack.push(start(&e)),
            Event::Empty(e) => {
                let n = start(&e);
                match stack.last_mut() {
                    Some(p) => p.children.push(n),
                    None => root = Some(n),
                }
            }
            Event::End(_) => {
                let n = stack.pop().unwrap();
                match stack.last_mut() {
                    Some(p) => p.children.push(n),
                    None => root = Some(n),
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    root.expect("a root element")
}

/// How a child may occur: name, minOccurs, maxOccurs (`None` = unbounded).
type Occ = (&'static str, u32, Option<u32>);

/// One element's rule: required attributes, and its content as a sequence of items, each
/// either one child (`Seq`) or a free-order choice of names (`Choice`).
enum Item {
    Seq(Occ),
    Choice(&'static [&'static str], u32, Option<u32>),
}

struct Rule {
    required: &'static [&'static str],
    content: Vec<Item>,
    /// Content not modelled (formatted text, type wrappers checked elsewhere).
    open: bool,
}

use Item::{Choice, Seq};

const ONE: Option<u32> = Some(1);
const MANY: Option<u32> = None;

fn rule(name: &str, parent: &str) -> Option<Rule> {
    let tail = || vec![Seq(("addData", 0, ONE)), Seq(("documentation", 0, ONE))];
    let with_tail = |mut v: Vec<Item>| {
        v.extend(tail());
        v
    };
    let r = |required, content| Some(Rule { required, content, open: false });
    let open = |required| Some(Rule { required, content: Vec::new(), open: true });
    match (parent, name) {
        (_, "project") => r(
            &[],
            vec![
                Seq(("fileHeader", 1, ONE)),
                Seq(("contentHeader", 1, ONE)),
                Seq(("types", 1, ONE)),
                Seq(("instances", 1, ONE)),
                Seq(("addData", 0, ONE)),
                Seq(("documentation", 0, ONE)),
            ],
        ),
        (_, "fileHeader") => {
            r(&["companyName", "productName", "productVersion", "creationDateTime"], vec![])
        }
        (_, "contentHeader") => r(
            &["name"],
            vec![
                Seq(("Comment", 0, ONE)),
                Seq(("coordinateInfo", 1, ONE)),
                Seq(("addDataInfo", 0, ONE)),
                Seq(("addData", 0, ONE)),
            ],
        ),
        (_, "coordinateInfo") => r(
            &[],
            vec![
                Seq(("pageSize", 0, ONE)),
                Seq(("fbd", 1, ONE)),
                Seq(("ld", 1, ONE)),
                Seq(("sfc", 1, ONE)),
            ],
        ),
        ("coordinateInfo", "fbd" | "ld" | "sfc") => r(&[], vec![Seq(("scaling", 1, ONE))]),
        (_, "scaling") => r(&["x", "y"], vec![]),
        (_, "types") => r(&[], vec![Seq(("dataTypes", 1, ONE)), Seq(("pous", 1, ONE))]),
        (_, "dataTypes") => r(&[], vec![Seq(("dataType", 0, MANY))]),
        (_, "dataType") => {
            r(&["name"], with_tail(vec![Seq(("baseType", 1, ONE)), Seq(("initialValue", 0, ONE))]))
        }
        (_, "pous") => r(&[], vec![Seq(("pou", 0, MANY))]),
        (_, "pou") => r(
            &["name", "pouType"],
            with_tail(vec![
                Seq(("interface", 0, ONE)),
                Seq(("actions", 0, ONE)),
                Seq(("transitions", 0, ONE)),
                Seq(("body", 0, MANY)),
            ]),
        ),
        (_, "interface") => r(
            &[],
            with_tail(vec![
                Seq(("returnType", 0, ONE)),
                Choice(
                    &[
                        "localVars",
                        "tempVars",
                        "inputVars",
                        "outputVars",
                        "inOutVars",
                        "externalVars",
                        "globalVars",
                        "accessVars",
                    ],
                    0,
                    MANY,
                ),
            ]),
        ),
        (
            _,
            "localVars" | "tempVars" | "inputVars" | "outputVars" | "inOutVars" | "externalVars"
            | "globalVars",
        ) => r(&[], with_tail(vec![Seq(("variable", 0, MANY))])),
        (
            "localVars" | "tempVars" | "inputVars" | "outputVars" | "inOutVars" | "externalVars"
            | "globalVars" | "struct",
            "variable",
        ) => r(&["name"], with_tail(vec![Seq(("type", 1, ONE)), Seq(("initialValue", 0, ONE))])),
        (_, "type" | "baseType" | "returnType" | "initialValue") => open(&[]),
        (_, "body") => r(&[], with_tail(vec![Choice(&["IL", "ST", "FBD", "LD", "SFC"], 1, ONE)])),
        ("body", "ST") | ("body", "IL") => r(&[], vec![Seq(("p", 1, ONE))]),
        ("body", "LD") => r(
            &[],
            vec![Choice(
                &[
                    "comment",
                    "error",
                    "connector",
                    "continuation",
                    "actionBlock",
                    "vendorElement",
                    "block",
                    "inVariable",
                    "outVariable",
                    "inOutVariable",
                    "label",
                    "jump",
                    "return",
                    "leftPowerRail",
                    "rightPowerRail",
                    "coil",
                    "contact",
                ],
                0,
                MANY,
            )],
        ),
        ("body", "FBD") => r(
            &[],
            vec![Choice(
                &[
                    "comment",
                    "error",
                    "connector",
                    "continuation",
                    "actionBlock",
                    "vendorElement",
                    "block",
                    "inVariable",
                    "outVariable",
                    "inOutVariable",
                    "label",
                    "jump",
                    "return",
                ],
                0,
                MANY,
            )],
        ),
        ("LD" | "FBD" | "SFC", "inOutVariable") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("expression", 1, ONE)),
            ]),
        ),
        ("LD" | "FBD" | "SFC", "connector") => r(
            &["localId", "name"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointIn", 0, ONE))]),
        ),
        ("LD" | "FBD" | "SFC", "continuation") => r(
            &["localId", "name"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointOut", 0, ONE))]),
        ),
        ("LD" | "SFC", "leftPowerRail") => r(
            &["localId"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointOut", 0, MANY))]),
        ),
        ("LD" | "SFC", "rightPowerRail") => r(
            &["localId"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointIn", 0, MANY))]),
        ),
        ("LD" | "SFC", "contact" | "coil") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("variable", 1, ONE)),
            ]),
        ),
        ("LD" | "FBD" | "SFC", "block") => r(
            &["localId", "typeName"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("inputVariables", 1, ONE)),
                Seq(("inOutVariables", 1, ONE)),
                Seq(("outputVariables", 1, ONE)),
            ]),
        ),
        ("block", "inputVariables" | "inOutVariables" | "outputVariables") => {
            r(&[], vec![Seq(("variable", 0, MANY))])
        }
        ("inputVariables", "variable") => r(
            &["formalParameter"],
            vec![Seq(("connectionPointIn", 1, ONE)), Seq(("documentation", 0, ONE))],
        ),
        ("inOutVariables", "variable") => r(
            &["formalParameter"],
            vec![
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("documentation", 0, ONE)),
            ],
        ),
        ("outputVariables", "variable") => r(
            &["formalParameter"],
            vec![Seq(("connectionPointOut", 0, ONE)), Seq(("documentation", 0, ONE))],
        ),
        ("LD" | "FBD" | "SFC", "inVariable") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("expression", 1, ONE)),
            ]),
        ),
        ("LD" | "FBD" | "SFC", "outVariable") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("expression", 1, ONE)),
            ]),
        ),
        ("LD" | "FBD" | "SFC", "label") => {
            r(&["localId", "label"], with_tail(vec![Seq(("position", 1, ONE))]))
        }
        ("LD" | "FBD" | "SFC", "jump") => r(
            &["localId", "label"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointIn", 0, ONE))]),
        ),
        ("LD" | "FBD" | "SFC", "return") => r(
            &["localId"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointIn", 0, ONE))]),
        ),
        ("LD" | "FBD" | "SFC", "comment") => r(
            &["localId", "height", "width"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("content", 1, ONE))]),
        ),
        ("body" | "inline", "SFC") => r(
            &[],
            vec![Choice(
                &[
                    "comment",
                    "error",
                    "connector",
                    "continuation",
                    "actionBlock",
                    "vendorElement",
                    "block",
                    "inVariable",
                    "outVariable",
                    "inOutVariable",
                    "label",
                    "jump",
                    "return",
                    "leftPowerRail",
                    "rightPowerRail",
                    "coil",
                    "contact",
                    "step",
                    "macroStep",
                    "jumpStep",
                    "transition",
                    "selectionDivergence",
                    "selectionConvergence",
                    "simultaneousDivergence",
                    "simultaneousConvergence",
                ],
                0,
                MANY,
            )],
        ),
        ("SFC", "step") => r(
            &["localId", "name"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("connectionPointOutAction", 0, ONE)),
            ]),
        ),
        (_, "connectionPointOutAction") => r(&[], vec![Seq(("relPosition", 0, ONE))]),
        ("SFC", "transition") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("condition", 0, ONE)),
            ]),
        ),
        ("transition", "condition") => {
            r(&[], with_tail(vec![Choice(&["reference", "connectionPointIn", "inline"], 1, ONE)]))
        }
        ("condition" | "action", "reference") => r(&["name"], vec![]),
        ("condition", "inline") => {
            r(&["name"], with_tail(vec![Choice(&["IL", "ST", "FBD", "LD", "SFC"], 1, ONE)]))
        }
        ("action", "inline") => {
            r(&[], with_tail(vec![Choice(&["IL", "ST", "FBD", "LD", "SFC"], 1, ONE)]))
        }
        ("inline", "ST") => r(&[], vec![Seq(("p", 1, ONE))]),
        ("SFC", "selectionDivergence" | "simultaneousDivergence") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 1, ONE)),
                Seq(("connectionPointOut", 0, MANY)),
            ]),
        ),
        ("SFC", "selectionConvergence" | "simultaneousConvergence") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, MANY)),
                Seq(("connectionPointOut", 1, ONE)),
            ]),
        ),
        ("SFC", "jumpStep") => r(
            &["localId", "targetName"],
            with_tail(vec![Seq(("position", 1, ONE)), Seq(("connectionPointIn", 0, ONE))]),
        ),
        ("LD" | "FBD" | "SFC", "actionBlock") => r(
            &["localId"],
            with_tail(vec![
                Seq(("position", 1, ONE)),
                Seq(("connectionPointIn", 0, ONE)),
                Seq(("action", 0, MANY)),
            ]),
        ),
        ("actionBlock", "action") => r(
            &["localId"],
            vec![
                Seq(("relPosition", 0, ONE)),
                Choice(&["reference", "inline"], 1, ONE),
                Seq(("connectionPointOut", 0, ONE)),
                Seq(("documentation", 0, ONE)),
            ],
        ),
        ("pou", "actions") => r(&[], vec![Seq(("action", 0, MANY))]),
        ("pou", "transitions") => r(&[], vec![Seq(("transition", 0, MANY))]),
        ("actions", "action") | ("transitions", "transition") => {
            r(&["name"], with_tail(vec![Seq(("body", 1, ONE))]))
        }
        (_, "position" | "relPosition") => r(&["x", "y"], vec![]),
        (_, "connectionPointIn") => r(
            &[],
            vec![Seq(("relPosition", 0, ONE)), Choice(&["connection", "expression"], 0, MANY)],
        ),
        (_, "connectionPointOut") => {
            r(&[], vec![Seq(("relPosition", 0, ONE)), Seq(("expression", 0, ONE))])
        }
        ("connectionPointIn", "connection") => {
            r(&["refLocalId"], vec![Seq(("position", 0, MANY)), Seq(("addData", 0, ONE))])
        }
        (_, "instances") => r(&[], vec![Seq(("configurations", 1, ONE))]),
        (_, "configurations") => r(&[], vec![Seq(("configuration", 0, MANY))]),
        (_, "configuration") => r(
            &["name"],
            with_tail(vec![
                Seq(("resource", 0, MANY)),
                Seq(("globalVars", 0, MANY)),
                Seq(("accessVars", 0, ONE)),
                Seq(("configVars", 0, ONE)),
            ]),
        ),
        (_, "resource") => r(
            &["name"],
            with_tail(vec![
                Seq(("task", 0, MANY)),
                Seq(("globalVars", 0, MANY)),
                Seq(("pouInstance", 0, MANY)),
            ]),
        ),
        (_, "task") => r(&["name", "priority"], with_tail(vec![Seq(("pouInstance", 0, MANY))])),
        ("configuration", "configVars") => {
            r(&[], with_tail(vec![Seq(("configVariable", 0, MANY))]))
        }
        ("configVars", "configVariable") => r(
            &["instancePathAndName"],
            with_tail(vec![Seq(("type", 1, ONE)), Seq(("initialValue", 0, ONE))]),
        ),
        (_, "pouInstance") => r(&["name", "typeName"], with_tail(vec![])),
        (_, "content" | "documentation" | "p" | "expression" | "variable" | "addData") => open(&[]),
        _ => None,
    }
}

/// Checks one element and its subtree; problems are pushed as `path: message`.
fn check(n: &Node, parent: &str, path: &str, out: &mut Vec<String>) {
    let here = format!("{path}/{}", n.name);
    let Some(rule) = rule(&n.name, parent) else {
        out.push(format!("{here}: <{}> is not allowed in <{parent}>", n.name));
        return;
    };
    for a in rule.required {
        if n.attr(a).is_none() {
            out.push(format!("{here}: required attribute {a} is missing"));
        }
    }
    check_values(n, &here, out);
    if rule.open {
        return;
    }
    let mut k = 0;
    for item in &rule.content {
        let (names, min, max): (Vec<&str>, u32, Option<u32>) = match item {
            Seq((name, min, max)) => (vec![name], *min, *max),
            Choice(names, min, max) => (names.to_vec(), *min, *max),
        };
        let mut count = 0;
        while k < n.children.len() && names.contains(&n.children[k].name.as_str()) {
            count += 1;
            k += 1;
        }
        if count < min || max.is_some_and(|m| count > m) {
            out.push(format!("{here}: {names:?} occurs {count} times (allowed {min}..{max:?})"));
        }
    }
    if let Some(extra) = n.children.get(k) {
        out.push(format!("{here}: <{}> is out of order or not allowed here", extra.name));
    }
    for c in &n.children {
        check(c, &n.name, &here, out);
    }
}

fn check_values(n: &Node, here: &str, out: &mut Vec<String>) {
    let mut bad = |what: &str, v: &str| out.push(format!("{here}: {what} = {v:?}"));
    for (k, v) in &n.attrs {
        match k.as_str() {
            "pouType" if !["function", "functionBlock", "program"].contains(&v.as_str()) => {
                bad(k, v)
            }
            "edge" if !["none", "rising", "falling"].contains(&v.as_str()) => bad(k, v),
            "storage" if !["none", "set", "reset"].contains(&v.as_str()) => bad(k, v),
            "negated" | "retain" | "constant" | "nonretain" if v != "true" && v != "false" => {
                bad(k, v)
            }
            "localId" | "refLocalId" | "priority" if v.parse::<u64>().is_err() => bad(k, v),
            "x" | "y" | "height" | "width" if v.parse::<f64>().is_err() => bad(k, v),
            _ => {}
        }
    }
}

/// localIds unique, references resolved, formal parameters of block outputs real.
fn check_body(ld: &Node, pou: &str, out: &mut Vec<String>) {
    let mut ids: HashMap<&str, &Node> = HashMap::new();
    for c in &ld.children {
        if let Some(id) = c.attr("localId") {
            if ids.insert(id, c).is_some() {
                out.push(format!("POU {pou}: localId {id} is used twice"));
            }
        }
    }
    fn connections<'a>(n: &'a Node, acc: &mut Vec<&'a Node>) {
        for c in &n.children {
            if c.name == "connection" {
                acc.push(c);
            }
            connections(c, acc);
        }
    }
    let mut conns = Vec::new();
    connections(ld, &mut conns);
    for c in conns {
        let r = c.attr("refLocalId").unwrap_or("");
        let Some(src) = ids.get(r) else {
            out.push(format!(
                "POU {pou}: a connection refers to localId {r}, which is not in the body"
            ));
            continue;
        };
        if let (Some(p), "block") = (c.attr("formalParameter"), src.name.as_str()) {
            let outputs = src
                .children
                .iter()
                .filter(|x| x.name == "outputVariables" || x.name == "inOutVariables")
                .flat_map(|x| &x.children)
                .filter_map(|v| v.attr("formalParameter"))
                .collect::<Vec<_>>();
            if !outputs.contains(&p) {
                out.push(format!("POU {pou}: a connection names output {p} of block {r}, which has outputs {outputs:?}"));
            }
        }
    }
}

/// Every structural problem of an exported document.
fn problems(xml: &str) -> Vec<String> {
    let root = parse(xml);
    let mut out = Vec::new();
    if root.ns.as_deref() != Some("http://www.plcopen.org/xml/tc6_0201") {
        out.push(format!("default namespace is {:?}", root.ns));
    }
    check(&root, "", "", &mut out);
    let pous: Vec<&Node> = root
        .children
        .iter()
        .filter(|c| c.name == "types")
        .flat_map(|t| &t.children)
        .filter(|c| c.name == "pous")
        .flat_map(|p| &p.children)
        .collect();
    let names: HashSet<&str> = pous.iter().filter_map(|p| p.attr("name")).collect();
    for p in &pous {
        for b in p.children.iter().filter(|c| c.name == "body") {
            for ld in b.children.iter().filter(|c| ["LD", "FBD", "SFC"].contains(&c.name.as_str()))
            {
                check_body(ld, p.attr("name").unwrap_or("?"), &mut out);
            }
        }
    }
    fn instances<'a>(n: &'a Node, acc: &mut Vec<&'a Node>) {
        for c in &n.children {
            if c.name == "pouInstance" {
                acc.push(c);
            }
            instances(c, acc);
        }
    }
    let mut insts = Vec::new();
    instances(&root, &mut insts);
    for i in insts {
        let t = i.attr("typeName").unwrap_or("");
        if !names.contains(t) {
            out.push(format!(
                "pouInstance {:?} names POU {t}, which is not in the file",
                i.attr("name")
            ));
        }
    }
    out
}

fn repo_root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every project the trainer has at hand: the examples, the samples as imported, and the
/// wiring cases of the other tests (rebuilt here through their XML).
fn projects() -> Vec<(String, Project)> {
    let mut out = Vec::new();
    let examples = repo_root().join("examples");
    let mut paths: Vec<_> =
        std::fs::read_dir(&examples).unwrap().map(|e| e.unwrap().path()).collect();
    paths.sort();
    for path in paths {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(&path).unwrap();
        let project = if name.ends_with(".json") {
            Project::from_file(&text).unwrap()
        } else if name.ends_with(".st") {
            let mut p = Project::new("example");
            p.source = text;
            p
        } else if name.ends_with(".xml") {
            import(&text).unwrap().project
        } else {
            continue;
        };
        out.push((name, project));
    }
    let samples = repo_root().join("tests/samples");
    let mut paths: Vec<_> =
        std::fs::read_dir(&samples).unwrap().map(|e| e.unwrap().path()).collect();
    paths.sort();
    for path in paths.into_iter().filter(|p| p.extension().is_some_and(|e| e == "xml")) {
        let name = path.display().to_string();
        out.push((name.clone(), load(&name).unwrap_or_else(|e| panic!("{name}: {e}")).project));
    }
    out
}

#[test]
fn every_exported_project_has_the_tc6_0201_structure() {
    let all = projects();
    let samples = all.iter().filter(|(n, _)| n.contains("tests/samples")).count();
    assert_eq!(samples, 8, "the samples of tests/samples");
    assert!(all.len() >= 9, "examples and samples found: {}", all.len());
    let mut ld_seen = HashSet::new();
    let all_kinds = ("all kinds".to_string(), all_kinds_project());
    for (name, p) in all.iter().chain([&all_kinds]) {
        let xml = export(p);
        let found = problems(&xml);
        assert!(found.is_empty(), "{name}:\n{}\n\n{xml}", found.join("\n"));
        for kind in [
            "leftPowerRail",
            "rightPowerRail",
            "contact",
            "coil",
            "block",
            "inVariable",
            "outVariable",
            "comment",
            "label",
            "jump",
            "return",
        ] {
            if xml.contains(&format!("<{kind} ")) {
                ld_seen.insert(kind);
            }
        }
    }
    assert_eq!(ld_seen.len(), 11, "LD elements covered: {ld_seen:?}");
}

/// The checker itself finds what it claims to: each rule broken once in a good document.
#[test]
fn the_structure_check_catches_each_kind_of_mistake() {
    let good = export(&all_kinds_project());
    assert!(problems(&good).is_empty(), "{:?}", problems(&good));
    let breaks: &[(&str, &str, &str)] = &[
        ("order", "<fileHeader", "<fileHeaderX"),
        ("namespace", "tc6_0201\"", "tc6_0200\""),
        ("required attribute", " pouType=\"program\"", ""),
        ("enum value", "pouType=\"program\"", "pouType=\"prog\""),
        ("missing coordinateInfo", "<coordinateInfo>", "<coordinateInfoX>"),
        ("dangling reference", "refLocalId=\"", "refLocalId=\"999"),
        ("position missing", "<position ", "<place "),
    ];
    for (what, from, to) in breaks {
        let bad = good.replacen(from, to, 1).replacen(
            &from.replace('<', "</"),
            &to.replace('<', "</"),
            1,
        );
        assert!(!problems(&bad).is_empty(), "{what} not caught");
    }
}

/// A project using every LD element kind and block feature the exporter writes: all
/// contact and coil kinds, a label, a jump and a return, a comment, a standard FB with a
/// wired input and an output, a data wire from an FB output, a user FB on EN/ENO with an
/// in-out, data types and globals.
fn all_kinds_project() -> Project {
    use plc_core::ladder::*;
    let c = |kind, v: &str| Element::Contact { kind, operand: v.into() };
    let q = |kind, v: &str| Element::Coil { kind, operand: v.into() };
    let row = |cells: Vec<Element>| -> Vec<Cell> {
        cells.into_iter().map(|element| Cell { element, link_down: false }).collect()
    };
    let mut r1 = Rung::new(2, 4);
    r1.comment = "every contact and coil".into();
    r1.cells[0] = row(vec![
        c(ContactKind::NormallyOpen, "a"),
        c(ContactKind::NormallyClosed, "b"),
        Element::Wire,
        q(CoilKind::Normal, "x"),
    ]);
    r1.cells[1] =
        row(vec![Element::Empty, Element::Empty, Element::Empty, q(CoilKind::Negated, "y")]);
    r1.cells[0][3].link_down = true;
    let mut r2 = Rung::new(1, 3);
    r2.cells[0] = row(vec![c(ContactKind::Rising, "a"), Element::Wire, q(CoilKind::Rising, "p")]);
    let mut r3 = Rung::new(2, 3);
    r3.cells[0] = row(vec![c(ContactKind::Falling, "a"), Element::Wire, q(CoilKind::Set, "s")]);
    r3.cells[1] = row(vec![Element::Empty, Element::Empty, q(CoilKind::Reset, "s2")]);
    r3.cells[0][2].link_down = true;
    let mut r4 = Rung::new(1, 2);
    r4.cells[0] =
        row(vec![c(ContactKind::NormallyOpen, "b"), Element::Jump { label: "Last".into() }]);
    let mut ctu = Block::new("CTU", Some("C1"));
    ctu.height = 3;
    ctu.inputs = vec![Pin::wired("R", 1), Pin::operand("PV", "3")];
    ctu.outputs = vec![Pin::operand("CV", "n")];
    let mut gt = Block::new("GT", None);
    gt.inputs = vec![Pin::operand("IN1", "C1.CV"), Pin::operand("IN2", "1")];
    let mut r5 = Rung::new(3, 4);
    r5.cells[0] = row(vec![
        c(ContactKind::NormallyOpen, "a"),
        Element::Block(ctu),
        Element::Block(gt),
        q(CoilKind::Normal, "big"),
    ]);
    r5.cells[1] = row(vec![
        c(ContactKind::NormallyOpen, "b"),
        Element::Covered,
        Element::Empty,
        Element::Empty,
    ]);
    r5.cells[2][1].element = Element::Covered;
    let mut acc = Block::new("Accumulate", Some("A1"));
    acc.height = 2;
    acc.inputs = vec![Pin::operand("Add", "n")];
    acc.in_outs = vec![Pin::operand("Sum", "total")];
    let mut r6 = Rung::new(2, 3);
    r6.label = Some("Last".into());
    r6.cells[0] = row(vec![
        c(ContactKind::NormallyOpen, "a"),
        Element::Block(acc),
        q(CoilKind::Normal, "x2"),
    ]);
    r6.cells[1][1].element = Element::Covered;
    let mut r7 = Rung::new(1, 2);
    r7.cells[0] = row(vec![c(ContactKind::NormallyOpen, "b"), Element::Return]);
    let lp = LadderPou {
        name: "Main".into(),
        kind: LadderPouKind::Program,
        declarations: "VAR_INPUT a : BOOL; b : BOOL; END_VAR\nVAR_OUTPUT x : BOOL; y : BOOL; END_VAR\nVAR p : BOOL; s : BOOL; s2 : BOOL; big : BOOL; x2 : BOOL; n : INT; total : INT; C1 : CTU; A1 : Accumulate; END_VAR\n".into(),
        rungs: vec![r1, r2, r3, r4, r5, r6, r7],
    };
    let mut p = Project::new("All kinds");
    p.source = "TYPE Level : INT(0..100); END_TYPE\nVAR_GLOBAL g : Level; END_VAR\nFUNCTION_BLOCK Accumulate\nVAR_INPUT Add : INT; END_VAR\nVAR_IN_OUT Sum : INT; END_VAR\nSum := Sum + Add;\nEND_FUNCTION_BLOCK\n".into();
    p.ladder = vec![lp];
    p
}

#[test]
fn the_all_kinds_project_is_valid_and_round_trips_through_its_export() {
    let p = all_kinds_project();
    let report = plc_core::run::run_project(&p, &plc_core::run::RunOptions::default());
    assert_eq!(report.status, plc_core::run::RunStatus::Ok, "{:?}", report.diagnostics);
    let xml = export(&p);
    assert!(problems(&xml).is_empty(), "{:?}", problems(&xml));
    let back = import(&xml).unwrap().project;
    let again = export(&back);
    assert_eq!(problems(&again), Vec::<String>::new());
    assert_eq!(import(&again).unwrap().project.ladder, back.ladder, "stable after one import");
}

#[test]
fn the_wired_inputs_and_data_wires_of_the_mixing_plant_export_cleanly() {
    let samples = projects();
    let (_, mixer) =
        samples.iter().find(|(n, _)| n.ends_with("ld_mixing_plant_shared_address.xml")).unwrap();
    let xml = export(mixer);
    assert!(problems(&xml).is_empty(), "{:?}", problems(&xml));
    // FillLatch's and MixLatch's R pins are wired to the contacts (and MixEnd) of their own
    // network, DrainLatch's R1 likewise.
    assert_eq!(xml.matches("<variable formalParameter=\"R\">").count(), 2);
    assert_eq!(xml.matches("<variable formalParameter=\"R1\">").count(), 1);
}

#[test]
fn var_config_entries_export_as_tc6_config_variables() {
    let mut p = Project::new("Configured");
    p.source = "FUNCTION_BLOCK Valve VAR_INPUT Setpoint : INT; END_VAR VAR_OUTPUT Open AT %Q* : BOOL; END_VAR Open := Setpoint > 0; END_FUNCTION_BLOCK
PROGRAM Cell VAR V1 : Valve; END_VAR V1(); END_PROGRAM
CONFIGURATION Plant
    PROGRAM Line : Cell;
    VAR_CONFIG
        Line.V1.Setpoint : INT := 50;
        Line.V1.Open AT %QX1.0 : BOOL := TRUE;
    END_VAR
END_CONFIGURATION
"
    .into();
    let xml = export(&p);
    assert!(xml.contains("<configVars>"), "{xml}");
    assert_eq!(problems(&xml), Vec::<String>::new(), "{xml}");
    let broken = xml.replacen(" instancePathAndName=\"Line.V1.Setpoint\"", "", 1);
    assert!(!problems(&broken).is_empty(), "a configVariable without its path is caught");
}
