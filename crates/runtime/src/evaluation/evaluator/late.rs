//! Outputs that nothing reads: which outputs of each node are wanted (wired to another node
//! or named as a graph output), and the others computed when a host first asks for them.
//!
//! A node's unread outputs are left empty when it runs, so that, say, Move's transform output
//! (one 4×4 matrix per moved point) costs nothing where only the moved geometry is used. The
//! first read of such an output through the evaluator's accessors runs the node again on its
//! current inputs, on the calling thread, and keeps the tree until the node runs again; a host
//! that reads every output can ask for all of them up front with
//! [`Evaluator::keep_all_outputs`].

use super::*;

impl Evaluator {
    /// Computes every output of every node from the next evaluation on, read or not (by
    /// default an output that no wire and no named output reads is computed only when it is
    /// first asked for, which runs its node again).
    pub fn keep_all_outputs(&mut self) {
        self.layout.wanted.fill(true);
    }

    /// Output `k` of node `i`: the stored tree, or, for an output the last run skipped, the
    /// tree computed on this first request.
    pub(super) fn tree(&self, i: usize, k: usize) -> &DataTree {
        let state = &self.states[i];
        if !state.skipped.get(k).copied().unwrap_or(false) {
            let j = self
                .layout
                .output_index(i, k)
                .unwrap_or_else(|| panic!("node {i} has no output {k}"));
            return &self.outputs[j];
        }
        state.late[k].get_or_init(|| {
            let budget = Budget {
                max_items: self.limits.max_items_per_output,
                watch: Watch::start(&self.limits),
            };
            let all = vec![true; state.skipped.len()];
            self.run_wanting(i, false, &budget, &all)
                .outputs
                .into_iter()
                .nth(k)
                .unwrap_or_default()
        })
    }
}
