//! FBD bodies (and LD networks off the rung grid) → ST statements through the network
//! lowering ([`crate::network::lower`]), each statement with the place in the file of the
//! element it was written from.

use super::ld_import::read::{read_elements, El};
use super::xml::Node;
use super::{ImportError, ImportNote};

/// A network body lowered: the statements and the instances it uses.
pub(crate) struct FbdBody {
    /// The body as ST statements, one per line, each with the line and column of the
    /// element it was written from.
    pub statements: Vec<(String, (u32, u32))>,
    /// `(instance, type)` of every function block instance in the body.
    pub instances: Vec<(String, String)>,
    /// What was left out (an output variable with no wire), with the element's place.
    pub notes: Vec<ImportNote>,
}

/// Lowers the FBD (or LD) body `fbd` of POU `pou`.
pub(crate) fn import_fbd(fbd: &Node, pou: &str) -> Result<FbdBody, ImportError> {
    let (els, left_out) = read_elements(fbd, pou)?;
    let mut body = lower_network(&els, pou)?;
    body.notes.extend(left_out);
    Ok(body)
}

/// Lowers the logical view `els` of a network of POU `pou`.
pub(crate) fn lower_network(els: &[El], pou: &str) -> Result<FbdBody, ImportError> {
    let lowered = crate::network::lower(els, pou).map_err(|e| element_error(pou, e))?;
    let at = |i: usize| els.get(i).map_or((0, 0), |e| e.at);
    Ok(FbdBody {
        statements: lowered.statements.into_iter().map(|(s, i)| (s, at(i))).collect(),
        instances: lowered.instances,
        notes: lowered
            .notes
            .into_iter()
            .map(|(i, message)| ImportNote::at(at(i).0, at(i).1, message))
            .collect(),
    })
}

/// A network error as an import error of POU `pou`.
pub(crate) fn element_error(pou: &str, e: crate::network::NetError) -> ImportError {
    ImportError::Element { pou: pou.to_string(), local_id: e.element, message: e.message }
}
