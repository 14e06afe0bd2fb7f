//! The software model's top level (IEC 61131-3 §2.7): a CONFIGURATION holds global
//! variables and RESOURCEs; a resource declares TASKs and the PROGRAM instances run under
//! them. Data only, like the rest of the AST.

use super::{DirectAddress, Expr, Ident, Initializer, TypeRef, VarBlock};
use crate::diagnostics::Span;

/// `CONFIGURATION name … END_CONFIGURATION`.
#[derive(Debug, Clone, PartialEq)]
pub struct Configuration {
    /// The configuration's name.
    pub name: Ident,
    /// Its own `VAR_GLOBAL` blocks (seen by every resource).
    pub globals: Vec<VarBlock>,
    /// Its resources; a configuration written without `RESOURCE` (tasks and programs
    /// straight inside it) has one resource named like the configuration.
    pub resources: Vec<Resource>,
    /// Its `VAR_CONFIG` entries: incomplete addresses (`%Q*`) of instances completed.
    pub var_config: Vec<ConfigVar>,
    /// The whole block.
    pub span: Span,
}

impl Configuration {
    /// Its VAR_GLOBAL blocks and its resources', in source order.
    pub fn global_blocks(&self) -> impl Iterator<Item = &VarBlock> {
        self.globals.iter().chain(self.resources.iter().flat_map(|r| &r.globals))
    }
}

/// `RESOURCE name ON type … END_RESOURCE`.
#[derive(Debug, Clone, PartialEq)]
pub struct Resource {
    /// The resource's name.
    pub name: Ident,
    /// The processor type after `ON`, if written.
    pub on: Option<Ident>,
    /// Its `VAR_GLOBAL` blocks.
    pub globals: Vec<VarBlock>,
    /// Its tasks.
    pub tasks: Vec<TaskDecl>,
    /// Its program instances.
    pub programs: Vec<ProgramDecl>,
    /// The whole block.
    pub span: Span,
}

/// `TASK name (SINGLE := …, INTERVAL := …, PRIORITY := …);`.
#[derive(Debug, Clone, PartialEq)]
pub struct TaskDecl {
    /// The task's name.
    pub name: Ident,
    /// `SINGLE :=`: the BOOL whose rising edge starts the task (an event task).
    pub single: Option<Expr>,
    /// `INTERVAL :=`: the period of a cyclic task.
    pub interval: Option<Expr>,
    /// `PRIORITY :=`: 0 is the most urgent.
    pub priority: Option<Expr>,
    /// The whole declaration.
    pub span: Span,
}

/// `PROGRAM name [WITH task] : Type [(In := source, Out => target)];`.
#[derive(Debug, Clone, PartialEq)]
pub struct ProgramDecl {
    /// The instance's name.
    pub name: Ident,
    /// The task it runs under (none: it runs on every scan, after the tasks).
    pub task: Option<Ident>,
    /// The PROGRAM type.
    pub type_name: Ident,
    /// Its connections to the configuration's variables.
    pub connections: Vec<Connection>,
    /// The whole declaration.
    pub span: Span,
}

/// One connection of a program instance: `In := source` (copied in before it runs) or
/// `Out => target` (copied out after).
#[derive(Debug, Clone, PartialEq)]
pub struct Connection {
    /// The program's VAR_INPUT or VAR_OUTPUT.
    pub param: Ident,
    /// True for `=>` (an output).
    pub output: bool,
    /// The configuration's variable.
    pub variable: Expr,
    /// The whole connection.
    pub span: Span,
}

/// One `VAR_CONFIG` entry: `Main1.Valve.Out AT %QX0.3 : BOOL;` gives the variable at the
/// instance path, declared at an incomplete address (`AT %Q* : BOOL`), its address;
/// `Main1.Valve.Setpoint : INT := 50;` gives it its initial value in that instance (both
/// may be given together).
#[derive(Debug, Clone, PartialEq)]
pub struct ConfigVar {
    /// The instance path: a program instance, then instance and variable names.
    pub path: Vec<Ident>,
    /// The complete address, when the entry gives one.
    pub location: Option<DirectAddress>,
    /// The declared type (the variable's).
    pub ty: TypeRef,
    /// The initial value, when the entry gives one.
    pub init: Option<Initializer>,
    /// The whole entry.
    pub span: crate::diagnostics::Span,
}
