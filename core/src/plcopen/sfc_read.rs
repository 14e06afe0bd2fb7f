//! What an SFC POU holds beside its chart's elements (which [`read_network`] reads into the
//! network model): the named actions and transitions of `<actions>` and `<transitions>`,
//! and the inline bodies of action blocks, each as ST. A body drawn in FBD is lowered to
//! ST statements on the way (and exported as ST), with a note saying so.
//!
//! [`read_network`]: super::ld_import::read::read_network

use super::ld_import::read::body_st;
use super::xml::Node;
use super::ImportNote;
use crate::diagnostics::Said;
use crate::network::NamedBody;

/// The named `<action>`s or `<transition>`s (`list` is `"actions"` or `"transitions"`) of
/// the POU element `pou`.
pub(crate) fn named_bodies(
    pou: &Node,
    list: &str,
    name: &str,
    notes: &mut Vec<ImportNote>,
) -> Result<Vec<NamedBody>, Said> {
    let actions = list == "actions";
    let item = if actions { "action" } else { "transition" };
    let mut out = Vec::new();
    for n in pou.child(list).into_iter().flat_map(|a| a.children_named(item)) {
        let bname = n.attr("name").unwrap_or("").trim().to_string();
        if bname.is_empty() {
            return Err(if actions {
                crate::msg!(PlcopenActionWithoutName)
            } else {
                crate::msg!(PlcopenTransitionWithoutName)
            });
        }
        let body = n.child("body").ok_or_else(|| {
            if actions {
                crate::msg!(PlcopenActionNoBody, name = &bname)
            } else {
                crate::msg!(PlcopenTransitionNoBody, name = &bname)
            }
        })?;
        if !actions && body.child("ST").is_none() {
            return Err(crate::msg!(PlcopenTransitionNotSt, name = &bname));
        }
        let st = body_st(body, name, notes).map_err(|m| {
            if actions {
                crate::msg!(PlcopenActionError, name = &bname, message = m)
            } else {
                crate::msg!(PlcopenTransitionError, name = &bname, message = m)
            }
        })?;
        out.push(NamedBody { name: bname, st, at: (n.line, n.column) });
    }
    Ok(out)
}
