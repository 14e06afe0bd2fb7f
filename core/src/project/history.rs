//! The undo/redo history every editor shares (ladder rungs, Petri nets, declarations).
//!
//! An editor keeps its current state `S` (the model it edits, and whatever else undo must
//! restore exactly, such as the selection) and records the state *before* each user action.
//! Undo swaps the current state with the last recorded one; redo swaps it back. Keeping
//! whole states rather than inverse operations makes undo exact by construction: an
//! operation cannot forget to invert a field.
//!
//! One user action is one step. Actions that arrive as many small edits (typing into a
//! property box, a drag reported on every pointer move) pass the same *group* key: while the
//! key repeats, only the state before the first edit of the group is kept.

/// How many steps a history keeps by default before it forgets the oldest.
pub const DEFAULT_HISTORY_LIMIT: usize = 200;

/// An undo/redo history of editor states.
#[derive(Debug, Clone, PartialEq)]
pub struct History<S> {
    past: Vec<S>,
    future: Vec<S>,
    limit: usize,
    /// The group of the last recorded step, while it may still absorb edits.
    open_group: Option<String>,
}

impl<S> Default for History<S> {
    fn default() -> Self {
        History::new(DEFAULT_HISTORY_LIMIT)
    }
}

impl<S> History<S> {
    /// An empty history that keeps at most `limit` undo steps (at least one).
    pub fn new(limit: usize) -> Self {
        History { past: Vec::new(), future: Vec::new(), limit: limit.max(1), open_group: None }
    }

    /// Records `before`, the state before an edit the user just made, as one undo step.
    /// Clears the redo steps.
    pub fn record(&mut self, before: S) {
        self.open_group = None;
        self.push(before);
    }

    /// Records `before` as an undo step unless the previous step was recorded with the same
    /// `group` and nothing was undone or recorded since: then the edit joins that step, so
    /// a whole drag or a burst of typing undoes at once.
    pub fn record_grouped(&mut self, before: S, group: &str) {
        if self.open_group.as_deref() == Some(group) {
            self.future.clear();
            return;
        }
        self.push(before);
        self.open_group = Some(group.to_string());
    }

    /// Ends the open group, so the next grouped edit starts a new step (call it when a drag
    /// ends or a property box loses the focus).
    pub fn close_group(&mut self) {
        self.open_group = None;
    }

    /// Undoes one step: returns the state to restore and keeps `current` for redo, or gives
    /// `current` back when there is nothing to undo.
    pub fn undo(&mut self, current: S) -> Result<S, S> {
        self.open_group = None;
        match self.past.pop() {
            Some(previous) => {
                self.future.push(current);
                Ok(previous)
            }
            None => Err(current),
        }
    }

    /// Redoes one undone step: returns the state to restore and keeps `current` for undo,
    /// or gives `current` back when there is nothing to redo.
    pub fn redo(&mut self, current: S) -> Result<S, S> {
        self.open_group = None;
        match self.future.pop() {
            Some(next) => {
                self.past.push(current);
                Ok(next)
            }
            None => Err(current),
        }
    }

    /// Takes back the last recorded step without keeping anything for redo: the edit it
    /// recorded was cancelled (Escape in an operand box), so the state before it returns.
    pub fn cancel(&mut self) -> Option<S> {
        self.open_group = None;
        self.past.pop()
    }

    /// Whether there is a step to undo.
    pub fn can_undo(&self) -> bool {
        !self.past.is_empty()
    }

    /// Whether there is a step to redo.
    pub fn can_redo(&self) -> bool {
        !self.future.is_empty()
    }

    /// Forgets every step (when the editor switches to another document).
    pub fn clear(&mut self) {
        self.past.clear();
        self.future.clear();
        self.open_group = None;
    }

    fn push(&mut self, before: S) {
        self.future.clear();
        if self.past.len() >= self.limit {
            self.past.remove(0);
        }
        self.past.push(before);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Applies `edit` to `state`, recording the state before it.
    fn edit(h: &mut History<Vec<u32>>, state: &mut Vec<u32>, value: u32) {
        h.record(state.clone());
        state.push(value);
    }

    #[test]
    fn undo_and_redo_restore_exact_states_in_order() {
        let mut h = History::default();
        let mut state = vec![];
        for v in 1..=20 {
            edit(&mut h, &mut state, v);
        }
        let after_all = state.clone();
        for expected_len in (0..20).rev() {
            state = h.undo(state).expect("a step to undo");
            assert_eq!(state, (1..=expected_len).collect::<Vec<_>>());
        }
        assert!(!h.can_undo());
        state = h.undo(state).expect_err("nothing left to undo");
        for _ in 0..20 {
            state = h.redo(state).expect("a step to redo");
        }
        assert_eq!(state, after_all);
        assert!(h.redo(state).is_err());
    }

    #[test]
    fn a_new_edit_after_undo_drops_the_redo_steps() {
        let mut h = History::default();
        let mut state = vec![];
        edit(&mut h, &mut state, 1);
        edit(&mut h, &mut state, 2);
        state = h.undo(state).expect("undo");
        edit(&mut h, &mut state, 3);
        assert!(!h.can_redo());
        assert_eq!(state, vec![1, 3]);
        state = h.undo(state).expect("undo");
        assert_eq!(state, vec![1]);
    }

    #[test]
    fn grouped_edits_undo_as_one_step_until_the_group_closes() {
        let mut h = History::default();
        let mut state = vec![0];
        for v in 1..=5 {
            h.record_grouped(state.clone(), "drag");
            state.push(v);
        }
        h.close_group();
        h.record_grouped(state.clone(), "drag");
        state.push(6);
        state = h.undo(state).expect("undo the second drag");
        assert_eq!(state, vec![0, 1, 2, 3, 4, 5]);
        state = h.undo(state).expect("undo the first drag");
        assert_eq!(state, vec![0]);
        assert!(!h.can_undo());
    }

    #[test]
    fn a_different_group_or_an_undo_starts_a_new_step() {
        let mut h = History::default();
        let mut state = vec![];
        h.record_grouped(state.clone(), "name");
        state.push(1);
        h.record_grouped(state.clone(), "guard");
        state.push(2);
        state = h.undo(state).expect("undo guard");
        h.record_grouped(state.clone(), "guard");
        state.push(3);
        assert_eq!(h.undo(state).expect("undo"), vec![1]);
    }

    #[test]
    fn the_oldest_steps_are_forgotten_past_the_limit() {
        let mut h = History::new(3);
        let mut state = vec![];
        for v in 1..=5 {
            edit(&mut h, &mut state, v);
        }
        for _ in 0..3 {
            state = h.undo(state).expect("undo");
        }
        assert_eq!(state, vec![1, 2]);
        assert!(!h.can_undo());
    }
}
