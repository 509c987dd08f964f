//! The view a solve function has of one iteration: typed inputs, outputs and messages.

/// One call of a node's solve function.
#[derive(Debug)]
pub struct Solve<'a> {
    _marker: std::marker::PhantomData<&'a ()>,
}
