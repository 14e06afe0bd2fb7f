//! `CONFIGURATION … END_CONFIGURATION`: global variables, resources, tasks and program
//! instances (IEC 61131-3 §2.7). `TASK`, `WITH`, `ON`, `SINGLE`, `INTERVAL`, `PRIORITY`,
//! `VAR_ACCESS` and `VAR_CONFIG` are recognised from context, so they stay usable as names
//! elsewhere.
//!
//! Recovery: a broken task or program declaration is skipped up to its `;`; a missing
//! `END_RESOURCE`/`END_CONFIGURATION` is reported at the opening keyword.

use super::{Fail, PResult, Parser};
use crate::diagnostics::Code;
use crate::phrase;
use crate::syntax::ast::*;
use crate::syntax::lexer::{Token, TokenKind};

impl Parser<'_> {
    /// Whether the current token is the contextual keyword `word`.
    fn at_word(&self, word: &str) -> bool {
        self.at(TokenKind::Ident) && self.text(self.tok()).eq_ignore_ascii_case(word)
    }

    /// A name, or "expected WHAT".
    fn name(&mut self, what: &str) -> PResult<Ident> {
        let t = self.expect(TokenKind::Ident, what)?;
        Ok(self.ident(t))
    }

    /// `CONFIGURATION name … END_CONFIGURATION` (the cursor is on `CONFIGURATION`).
    pub(super) fn parse_configuration(&mut self) -> Configuration {
        let opener = self.bump();
        let name = self
            .name("the configuration's name after `CONFIGURATION`")
            .unwrap_or(Ident { name: String::new(), span: opener.span });
        let mut config = Configuration {
            name,
            globals: Vec::new(),
            resources: Vec::new(),
            var_config: Vec::new(),
            span: opener.span,
        };
        // Tasks and programs written straight inside the configuration form one resource.
        let mut single = Resource {
            name: config.name.clone(),
            on: None,
            globals: Vec::new(),
            tasks: Vec::new(),
            programs: Vec::new(),
            span: opener.span,
        };
        loop {
            let before = self.pos;
            match self.peek() {
                TokenKind::EndConfiguration => {
                    self.bump();
                    self.eat(TokenKind::Semicolon);
                    break;
                }
                TokenKind::VarGlobal => {
                    if let Some(b) = self.parse_var_block() {
                        config.globals.push(b);
                    }
                }
                TokenKind::Resource => config.resources.push(self.parse_resource()),
                TokenKind::Ident if self.at_word("VAR_CONFIG") => {
                    self.parse_var_config(&mut config)
                }
                TokenKind::Program if self.program_is_pou() => {
                    self.unclosed(opener, "END_CONFIGURATION");
                    break;
                }
                TokenKind::Eof
                | TokenKind::Function
                | TokenKind::FunctionBlock
                | TokenKind::Type => {
                    self.unclosed(opener, "END_CONFIGURATION");
                    break;
                }
                _ => self.resource_item(&mut single),
            }
            if self.pos == before {
                self.bump();
            }
        }
        config.span = opener.span.to(self.prev_span());
        if !single.tasks.is_empty() || !single.programs.is_empty() {
            single.span = config.span;
            config.resources.insert(0, single);
        }
        config
    }

    /// Whether `PROGRAM` at the cursor opens a POU (`PROGRAM Name` followed by a
    /// declaration block, a statement or END_PROGRAM) rather than declaring an instance
    /// (`PROGRAM Name WITH …` or `PROGRAM Name : Type`).
    fn program_is_pou(&self) -> bool {
        let next = self.peek_at(2);
        let word = self.text(self.nth(2));
        !(next == TokenKind::Colon
            || (next == TokenKind::Ident && word.eq_ignore_ascii_case("WITH"))
            || matches!(self.peek_at(1), TokenKind::Retain | TokenKind::NonRetain))
    }

    fn unclosed(&mut self, opener: Token, end: &str) {
        let text = self.text(opener).to_string();
        self.error(Code::MissingEnd, opener.span, format!("`{text}` is never closed; add `{end}`"));
    }

    /// `RESOURCE name ON type … END_RESOURCE` (the cursor is on `RESOURCE`).
    fn parse_resource(&mut self) -> Resource {
        let opener = self.bump();
        let name = self
            .name("the resource's name after `RESOURCE`")
            .unwrap_or(Ident { name: String::new(), span: opener.span });
        let mut res = Resource {
            name,
            on: None,
            globals: Vec::new(),
            tasks: Vec::new(),
            programs: Vec::new(),
            span: opener.span,
        };
        if self.at_word("ON") {
            self.bump();
            res.on = self.name("the processor type after `ON`").ok();
        }
        loop {
            let before = self.pos;
            match self.peek() {
                TokenKind::EndResource => {
                    self.bump();
                    self.eat(TokenKind::Semicolon);
                    break;
                }
                TokenKind::VarGlobal => {
                    if let Some(b) = self.parse_var_block() {
                        res.globals.push(b);
                    }
                }
                TokenKind::Eof
                | TokenKind::EndConfiguration
                | TokenKind::Resource
                | TokenKind::Function
                | TokenKind::FunctionBlock
                | TokenKind::Type => {
                    self.unclosed(opener, "END_RESOURCE");
                    break;
                }
                TokenKind::Program if self.program_is_pou() => {
                    self.unclosed(opener, "END_RESOURCE");
                    break;
                }
                _ => self.resource_item(&mut res),
            }
            if self.pos == before {
                self.bump();
            }
        }
        res.span = opener.span.to(self.prev_span());
        res
    }

    /// One item of a resource: a TASK, a PROGRAM instance, or a skipped VAR_ACCESS /
    /// VAR_CONFIG block; anything else is reported and skipped to its `;`.
    fn resource_item(&mut self, res: &mut Resource) {
        let r = if self.at_word("TASK") {
            self.parse_task().map(|t| res.tasks.push(t))
        } else if self.at(TokenKind::Program) {
            self.parse_program_decl().map(|p| res.programs.push(p))
        } else if self.at_word("VAR_ACCESS") {
            self.skip_access_block();
            Ok(())
        } else {
            Err(self
                .expected("`TASK`, `PROGRAM`, `RESOURCE`, `VAR_GLOBAL` or the END of the block"))
        };
        if r.is_err() {
            while !matches!(
                self.peek(),
                TokenKind::Semicolon
                    | TokenKind::Eof
                    | TokenKind::EndResource
                    | TokenKind::EndConfiguration
            ) {
                self.bump();
            }
            self.eat(TokenKind::Semicolon);
        }
    }

    /// `VAR_CONFIG path AT %… : TYPE; … END_VAR` (the cursor is on `VAR_CONFIG`); a broken
    /// entry is reported and skipped to its `;`.
    fn parse_var_config(&mut self, config: &mut Configuration) {
        self.bump();
        loop {
            match self.peek() {
                TokenKind::EndVar => {
                    self.bump();
                    return;
                }
                TokenKind::Eof | TokenKind::EndConfiguration | TokenKind::Resource => {
                    let span = self.tok().span;
                    self.error(
                        Code::MissingEnd,
                        span,
                        "`VAR_CONFIG` is never closed; add `END_VAR`",
                    );
                    return;
                }
                _ => {}
            }
            let before = self.pos;
            match self.config_entry() {
                Ok(entry) => config.var_config.push(entry),
                Err(Fail) => {
                    while !matches!(
                        self.peek(),
                        TokenKind::Semicolon
                            | TokenKind::EndVar
                            | TokenKind::Eof
                            | TokenKind::EndConfiguration
                    ) {
                        self.bump();
                    }
                    self.eat(TokenKind::Semicolon);
                }
            }
            if self.pos == before {
                self.bump();
            }
        }
    }

    /// `Main1.Valve.Out AT %QX0.3 : BOOL;`, `Main1.Valve.Setpoint : INT := 50;` or both:
    /// `Main1.Valve.Out AT %QX0.3 : BOOL := TRUE;`
    fn config_entry(&mut self) -> PResult<ConfigVar> {
        let start = self.tok().span;
        let mut path = vec![self.name("an instance path such as `Main1.Valve.Out`")?];
        while self.eat(TokenKind::Dot).is_some() {
            path.push(self.name("a name after `.`")?);
        }
        let location = if self.eat(TokenKind::At).is_some() {
            let tok = self.expect(TokenKind::Direct, phrase!(ExpectAddressQx03AfterAt))?;
            Some(self.direct_address(tok).ok_or(Fail)?)
        } else {
            None
        };
        let what = if location.is_some() {
            "`:` and the variable's type"
        } else {
            "`AT` and the variable's address, or `:` and its type"
        };
        self.expect(TokenKind::Colon, what)?;
        let ty = self.parse_type_spec()?;
        let init = match self.eat(TokenKind::Assign) {
            Some(_) => Some(self.parse_initializer()?),
            None => None,
        };
        self.expect(TokenKind::Semicolon, phrase!(ExpectSemicolonAfterEntry))?;
        Ok(ConfigVar { path, location, ty, init, span: start.to(self.prev_span()) })
    }

    /// `VAR_ACCESS … END_VAR`: reported and skipped.
    fn skip_access_block(&mut self) {
        let opener = self.bump();
        let text = self.text(opener).to_string();
        self.error(
            Code::UnsupportedConfiguration,
            opener.span,
            format!("`{text}` blocks are not supported yet; remove the block (its variables can be declared in VAR_GLOBAL)"),
        );
        while !matches!(
            self.peek(),
            TokenKind::EndVar | TokenKind::Eof | TokenKind::EndConfiguration
        ) {
            self.bump();
        }
        self.eat(TokenKind::EndVar);
    }

    /// `TASK name (SINGLE := …, INTERVAL := …, PRIORITY := …);`
    fn parse_task(&mut self) -> PResult<TaskDecl> {
        let start = self.bump().span;
        let name = self.name("the task's name after `TASK`")?;
        let mut task = TaskDecl { name, single: None, interval: None, priority: None, span: start };
        self.expect(TokenKind::LParen, phrase!(ExpectParenAndTaskSIntervalPriorityOr))?;
        loop {
            let key = self.name("`INTERVAL`, `PRIORITY` or `SINGLE`")?;
            self.expect(TokenKind::Assign, phrase!(ExpectAssign))?;
            let value = self.parse_expr()?;
            let slot = match key.key().as_str() {
                "SINGLE" => &mut task.single,
                "INTERVAL" => &mut task.interval,
                "PRIORITY" => &mut task.priority,
                _ => {
                    self.error(
                        Code::UnexpectedToken,
                        key.span,
                        format!("a task has INTERVAL, PRIORITY and SINGLE, not `{}`", key.name),
                    );
                    return Err(Fail);
                }
            };
            if slot.is_some() {
                self.error(
                    Code::DuplicateArgument,
                    key.span,
                    format!("`{}` is given twice", key.name),
                );
            }
            *slot = Some(value);
            if self.eat(TokenKind::Comma).is_none() {
                break;
            }
        }
        self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParen))?;
        self.expect(TokenKind::Semicolon, phrase!(ExpectSemicolonAfterTask))?;
        task.span = start.to(self.prev_span());
        Ok(task)
    }

    /// `PROGRAM [RETAIN|NON_RETAIN] name [WITH task] : Type [( connections )];`
    fn parse_program_decl(&mut self) -> PResult<ProgramDecl> {
        let start = self.bump().span;
        if matches!(self.peek(), TokenKind::Retain | TokenKind::NonRetain) {
            self.bump();
        }
        let name = self.name("the program instance's name")?;
        let task = if self.at_word("WITH") {
            self.bump();
            Some(self.name("a task name after `WITH`")?)
        } else {
            None
        };
        self.expect(TokenKind::Colon, phrase!(ExpectColonAndProgramType))?;
        let type_name = self.name("the PROGRAM type")?;
        let mut connections = Vec::new();
        if self.eat(TokenKind::LParen).is_some() && self.eat(TokenKind::RParen).is_none() {
            loop {
                let param = self.name("a parameter of the program")?;
                let output = match self.peek() {
                    TokenKind::Assign => false,
                    TokenKind::Arrow => true,
                    _ => return Err(self.expected(phrase!(ExpectAssignOrArrow))),
                };
                self.bump();
                let variable = self.parse_expr()?;
                let span = param.span.to(variable.span);
                connections.push(Connection { param, output, variable, span });
                if self.eat(TokenKind::Comma).is_none() {
                    break;
                }
            }
            self.expect(TokenKind::RParen, phrase!(ExpectCommaOrCloseParen))?;
        }
        self.expect(TokenKind::Semicolon, phrase!(ExpectSemicolonAfterProgramInstance))?;
        Ok(ProgramDecl { name, task, type_name, connections, span: start.to(self.prev_span()) })
    }
}
