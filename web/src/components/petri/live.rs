//! The token game read back from the running program: which transitions are enabled by
//! the current marking, and which fired on the last scan (the marking before and after it
//! explained by the net's arcs). Pure functions, tested natively.

/// Per transition: whether every input place holds at least the arc's weight.
pub fn enabled(pre: &[Vec<(usize, u32)>], marking: &[u32]) -> Vec<bool> {
    pre.iter()
        .map(|ins| {
            !ins.is_empty() && ins.iter().all(|&(p, w)| marking.get(p).is_some_and(|&m| m >= w))
        })
        .collect()
}

/// Per transition: whether it explains the step from marking `before` to `after` — it was
/// enabled before, every place it marks is marked after, and every place it empties (an
/// input that is not also an output) lost its token. Nothing fired when the marking did not
/// change.
pub fn fired(
    pre: &[Vec<(usize, u32)>],
    post: &[Vec<(usize, u32)>],
    before: &[u32],
    after: &[u32],
) -> Vec<bool> {
    let was_enabled = enabled(pre, before);
    let unchanged = before == after;
    let at = |m: &[u32], p: usize| m.get(p).copied().unwrap_or(0);
    pre.iter()
        .zip(post)
        .zip(was_enabled)
        .map(|((ins, outs), on)| {
            on && !unchanged
                && outs.iter().all(|&(p, w)| at(after, p) >= w)
                && ins
                    .iter()
                    .filter(|(p, _)| !outs.iter().any(|(q, _)| q == p))
                    .all(|&(p, _)| at(after, p) < at(before, p))
        })
        .collect()
}

#[cfg(test)]
mod tests;
