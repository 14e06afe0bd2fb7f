//! How a block on a rung becomes ST: the call (or expression) it stands for, gated by its
//! enable, and the power it passes on. Shared by the lowering and the readable ST view so the
//! two cannot disagree.
//!
//! The rules (see [`Block`]): a block whose power input is `EN` runs only when power reaches
//! it (`IF power THEN … END_IF;`), so its outputs keep their values on other scans and `ENO`
//! is the power itself; a block whose power input is a BOOL input (`IN` of a timer) runs on
//! every scan with that input following the power.

use super::model::{is_comparison, Block};
use crate::syntax::Cmp;

/// The power a block passes on, relative to the power reaching it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum PowerOut {
    /// The power reaching the block (`ENO` of a block with `EN`).
    Same,
    /// The power reaching the block AND this BOOL value (a comparison, an output of a block
    /// with `EN`).
    And(String),
    /// The power reaching the block AND THEN this value (a user function's result, which must
    /// not be computed when the block is not enabled).
    AndThen(String),
    /// This BOOL value alone (`Q` of a timer).
    Value(String),
}

impl PowerOut {
    /// The power as one ST expression, given the ST expression of the power reaching the block.
    pub fn render(&self, power: &str) -> String {
        match self {
            PowerOut::Same => power.to_string(),
            PowerOut::And(x) if power == "TRUE" => x.clone(),
            PowerOut::And(x) => format!("{power} AND {x}"),
            PowerOut::AndThen(x) if power == "TRUE" => x.clone(),
            PowerOut::AndThen(x) => format!("{power} AND_THEN {x}"),
            PowerOut::Value(x) => x.clone(),
        }
    }
}

/// The ST a block stands for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct BlockCode {
    /// The statements, already gated by the enable when the block has one.
    pub statements: Vec<String>,
    /// The power it passes on.
    pub power_out: PowerOut,
}

fn compare_op(name: &str) -> Option<&'static str> {
    Cmp::from_function(name.trim()).map(Cmp::symbol)
}

fn binary_op(name: &str) -> Option<&'static str> {
    Some(match name.trim().to_ascii_uppercase().as_str() {
        "ADD" => "+",
        "SUB" => "-",
        "MUL" => "*",
        "DIV" => "/",
        "MOD" => "MOD",
        "AND" => "AND",
        "OR" => "OR",
        "XOR" => "XOR",
        _ => return None,
    })
}

/// Standard functions that are operators or builtins (not user FUNCTIONs of the project).
pub(crate) const STANDARD_FUNCTIONS: &[&str] = &[
    "EQ",
    "NE",
    "GT",
    "GE",
    "LT",
    "LE",
    "ADD",
    "SUB",
    "MUL",
    "DIV",
    "MOD",
    "SQRT",
    "MOVE",
    "AND",
    "OR",
    "XOR",
    "NOT",
    "SHL",
    "SHR",
    "ROL",
    "ROR",
    "BCD_TO_INT",
    "INT_TO_BCD",
];

/// Whether `name` is one of the [`STANDARD_FUNCTIONS`] or a type conversion.
pub(crate) fn is_standard_function(name: &str) -> bool {
    STANDARD_FUNCTIONS.iter().any(|n| n.eq_ignore_ascii_case(name.trim())) || is_conversion(name)
}

/// Whether `name` is a conversion between elementary types (`BOOL_TO_INT`, `REAL_TO_DINT`),
/// one input `IN` and the output `OUT` of the type its name ends in.
pub(crate) fn is_conversion(name: &str) -> bool {
    let upper = name.trim().to_ascii_uppercase();
    let elementary = |t: &str| {
        crate::semantic::types::Elem::from_name(t).is_some() || t == "STRING" || t == "WSTRING"
    };
    upper.split_once("_TO_").is_some_and(|(from, to)| elementary(from) && elementary(to))
}

/// Whether a block is a function block (has an instance) rather than a function.
pub(crate) fn is_fb(b: &Block) -> bool {
    super::model::standard_fb_power(&b.type_name).is_some()
        || b.instance.as_deref().is_some_and(|i| !i.trim().is_empty())
}

/// The input values of a block in call order: `(pin name, ST value)`. Wired inputs take the
/// value given in `wired` (by input index); `IN1`, `IN2`, … are put in number order.
fn input_values<'a>(b: &'a Block, wired: &[Option<String>]) -> Vec<(&'a str, String)> {
    let mut v: Vec<(&str, String)> = b
        .inputs
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let value = match wired.get(k).cloned().flatten() {
                Some(w) => w,
                None => p.operand.trim().to_string(),
            };
            (p.name.trim(), value)
        })
        .collect();
    let number = |n: &str| -> Option<u32> {
        n.get(..2).filter(|p| p.eq_ignore_ascii_case("IN")).and_then(|_| n[2..].parse().ok())
    };
    if v.iter().all(|(n, _)| number(n).is_some()) {
        crate::order::sort_by_key(&mut v, |(n, _)| number(n));
    }
    v
}

/// The value a standard function computes, as ST (`a + b`, `SQRT(x)`, `SHL(IN := x, N := 2)`).
fn standard_value(b: &Block, args: &[(&str, String)]) -> String {
    let name = b.type_name.trim();
    if let Some(op) = binary_op(name) {
        if args.len() >= 2 {
            return args
                .iter()
                .map(|(_, a)| format!("({a})"))
                .collect::<Vec<_>>()
                .join(&format!(" {op} "));
        }
    }
    if let Some(op) = compare_op(name) {
        if args.len() < 2 {
            return "FALSE".to_string();
        }
        return args
            .windows(2)
            .map(|w| format!("({} {op} {})", w[0].1, w[1].1))
            .collect::<Vec<_>>()
            .join(" AND ");
    }
    match (name.to_ascii_uppercase().as_str(), args) {
        ("MOVE", [(_, a), ..]) => a.clone(),
        ("NOT", [(_, a), ..]) => format!("NOT ({a})"),
        (_, [(_, a)]) => format!("{name}({a})"),
        _ => {
            let list: Vec<String> = args.iter().map(|(n, a)| format!("{n} := {a}")).collect();
            format!("{name}({})", list.join(", "))
        }
    }
}

/// The ST of `b` reached by `power` (an ST expression), with the values of its wired inputs.
pub(crate) fn block_code(b: &Block, power: &str, wired: &[Option<String>]) -> BlockCode {
    let enable = b.has_enable();
    let power_in = b.power_input().to_string();
    let power_out = b.power_output().to_string();
    let args = input_values(b, wired);
    let mut statements = Vec::new();
    let out = if is_fb(b) {
        let inst = b.instance.as_deref().unwrap_or_default().trim().to_string();
        let mut list = Vec::new();
        if !enable {
            list.push(format!("{power_in} := {power}"));
        }
        list.extend(args.iter().map(|(n, v)| format!("{n} := {v}")));
        list.extend(b.in_outs.iter().map(|p| format!("{} := {}", p.name.trim(), p.operand.trim())));
        statements.push(format!("{inst}({});", list.join(", ")));
        for p in &b.outputs {
            statements.push(format!("{} := {inst}.{};", p.operand.trim(), p.name.trim()));
        }
        if power_out.eq_ignore_ascii_case("ENO") {
            PowerOut::Same
        } else if enable {
            PowerOut::And(format!("{inst}.{power_out}"))
        } else {
            PowerOut::Value(format!("{inst}.{power_out}"))
        }
    } else {
        let mut args = args;
        if !enable {
            args.insert(0, (power_in.as_str(), power.to_string()));
        }
        let standard = is_standard_function(&b.type_name);
        let result = b
            .outputs
            .iter()
            .find(|p| p.name.trim().eq_ignore_ascii_case("OUT"))
            .or_else(|| b.outputs.first().filter(|_| standard))
            .map(|p| p.operand.trim().to_string());
        let value = if standard {
            standard_value(b, &args)
        } else {
            let mut list: Vec<String> = args.iter().map(|(n, v)| format!("{n} := {v}")).collect();
            list.extend(
                b.in_outs.iter().map(|p| format!("{} := {}", p.name.trim(), p.operand.trim())),
            );
            list.extend(
                b.outputs
                    .iter()
                    .filter(|p| !p.name.trim().eq_ignore_ascii_case("OUT"))
                    .map(|p| format!("{} => {}", p.name.trim(), p.operand.trim())),
            );
            format!("{}({})", b.type_name.trim(), list.join(", "))
        };
        let comparison = is_comparison(&b.type_name);
        let eno = power_out.eq_ignore_ascii_case("ENO");
        match &result {
            Some(var) => statements.push(format!("{var} := {value};")),
            // Called for its outputs and in-outs only when its result carries no power.
            None if !standard && eno => statements.push(format!("{value};")),
            None => {}
        }
        let carried = result.clone().unwrap_or_else(|| value.clone());
        if eno {
            PowerOut::Same
        } else if !enable {
            PowerOut::Value(carried)
        } else if result.is_some() {
            PowerOut::And(carried)
        } else if comparison || standard {
            statements.clear();
            PowerOut::And(value)
        } else {
            statements.clear();
            PowerOut::AndThen(value)
        }
    };
    if enable && power != "TRUE" && !statements.is_empty() {
        let body = statements.join(" ");
        statements = vec![format!("IF {power} THEN {body} END_IF;")];
    }
    BlockCode { statements, power_out: out }
}
