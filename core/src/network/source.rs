//! A network POU as ST text for the checker: its header, declarations (with the function
//! block instances its blocks use and the declarations lack), the lowered statements (an
//! SFC's textual chart) and its END keyword, with the element each line was written from.

use std::ops::Range;

use super::model::{NetworkLanguage, NetworkPou, NetworkPouKind};
use super::NetError;

/// A network POU written as ST.
#[derive(Debug, Clone, PartialEq)]
pub struct NetworkText {
    /// The POU's ST text.
    pub st: String,
    /// The 1-based lines of `st` that are the POU's declarations.
    pub declaration_lines: Range<u32>,
    /// Entry `k`: the `localId` of the element line `k + 1` of `st` was written from.
    pub lines: Vec<Option<String>>,
}

impl NetworkPou {
    /// The POU's first line: `PROGRAM Name`, `FUNCTION Name : TYPE`.
    pub fn header(&self) -> String {
        match (&self.kind, &self.return_type) {
            (NetworkPouKind::Function, Some(t)) => format!("FUNCTION {} : {t}", self.name),
            (kind, _) => format!("{} {}", kind.keyword(), self.name),
        }
    }

    /// The POU's interface alone (header, declarations, END), for block catalogs.
    pub fn signature(&self) -> String {
        format!("{}\n{}\nEND_{}\n", self.header(), self.declarations, self.kind.keyword())
    }

    /// The POU as ST text (see the module comment).
    pub fn to_st(&self) -> Result<NetworkText, NetError> {
        let (body, instances) = match self.language {
            NetworkLanguage::Sfc => {
                let chart = super::chart::chart_text(self)?;
                (chart.lines, chart.instances)
            }
            NetworkLanguage::Ld | NetworkLanguage::Fbd => {
                let els = super::logical(&self.elements)?;
                let lowered = super::lower(&els, &self.name)?;
                let id = |i: usize| els.get(i).map(|e| e.id.clone());
                let body = lowered.statements.into_iter().map(|(s, i)| (s, id(i))).collect();
                (body, lowered.instances)
            }
        };
        let mut st = String::new();
        let mut lines: Vec<Option<String>> = Vec::new();
        let mut push = |st: &mut String, text: &str, element: Option<&str>| {
            for line in text.lines() {
                st.push_str(line);
                st.push('\n');
                lines.push(element.map(str::to_string));
            }
        };
        push(&mut st, &self.header(), None);
        let first_declaration = st.lines().count() as u32 + 1;
        push(&mut st, &self.declarations, None);
        let mut missing: Vec<&(String, String)> = Vec::new();
        for inst in &instances {
            if !declares(&self.declarations, &inst.0)
                && !missing.iter().any(|m| m.0.eq_ignore_ascii_case(&inst.0))
            {
                missing.push(inst);
            }
        }
        if !missing.is_empty() {
            push(&mut st, "VAR", None);
            for (inst, ty) in missing {
                push(&mut st, &format!("    {inst} : {ty};"), None);
            }
            push(&mut st, "END_VAR", None);
        }
        let declaration_lines = first_declaration..st.lines().count() as u32 + 1;
        for (text, element) in &body {
            push(&mut st, text, element.as_deref());
        }
        push(&mut st, &format!("END_{}", self.kind.keyword()), None);
        st.push('\n');
        lines.push(None);
        Ok(NetworkText { st, declaration_lines, lines })
    }
}

/// Whether `declarations` declare `name` (a whole word before a colon).
pub fn declares(declarations: &str, name: &str) -> bool {
    declarations.lines().any(|l| {
        l.split(':')
            .next()
            .is_some_and(|names| names.split(',').any(|n| n.trim().eq_ignore_ascii_case(name)))
    })
}
