//! Helpers shared by the node tests of every category: reading typed items out of output trees
//! and checking the messages of a call.
//!
//! A helper panics on anything unexpected (a null, another type, a missing message), which
//! fails the test that called it with a message naming what was found.

use locus_runtime::{DataTree, Item, Level, NodeCallResult, Value};

/// The items of an output tree as `T`, in order, `None` for nulls (panics on another type).
pub(crate) fn items<T: Item + std::fmt::Debug>(tree: &DataTree) -> Vec<Option<T>> {
    tree.values()
        .map(|v| {
            v.map(|v| {
                v.get::<T>()
                    .unwrap_or_else(|| panic!("expected a {}, got {v:?}", T::TYPE))
            })
        })
        .collect()
}

/// The items of an output tree as `T`, in order (panics on a null or another type).
pub(crate) fn all<T: Item + std::fmt::Debug>(tree: &DataTree) -> Vec<T> {
    items::<T>(tree)
        .into_iter()
        .enumerate()
        .map(|(i, v)| v.unwrap_or_else(|| panic!("expected a {}, got null at {i}", T::TYPE)))
        .collect()
}

/// The items of an output tree, in order, `None` for nulls.
pub(crate) fn values(tree: &DataTree) -> Vec<Option<Value>> {
    tree.values().collect()
}

/// The numbers of an output tree.
pub(crate) fn numbers(tree: &DataTree) -> Vec<f64> {
    all(tree)
}

/// The booleans of an output tree.
pub(crate) fn booleans(tree: &DataTree) -> Vec<bool> {
    all(tree)
}

/// The points of an output tree.
pub(crate) fn points(tree: &DataTree) -> Vec<locus_kernel::Point3> {
    all(tree)
}

/// The vectors of an output tree.
pub(crate) fn vectors(tree: &DataTree) -> Vec<locus_kernel::Vector3> {
    all(tree)
}

/// The domains of an output tree.
pub(crate) fn domains(tree: &DataTree) -> Vec<locus_kernel::Interval> {
    all(tree)
}

/// The curves of an output tree.
pub(crate) fn curves(tree: &DataTree) -> Vec<locus_runtime::Shared<locus_kernel::Curve>> {
    all(tree)
}

/// The only item of output `output` (panics unless there is exactly one non-null item).
pub(crate) fn only<T: Item + std::fmt::Debug>(result: &NodeCallResult, output: usize) -> T {
    let all = items::<T>(&result.outputs[output]);
    assert_eq!(all.len(), 1, "expected one item, got {all:?}");
    all.into_iter()
        .next()
        .flatten()
        .unwrap_or_else(|| panic!("output {output} is null; messages: {:?}", result.messages))
}

/// The only value of output `output`, whatever its type.
pub(crate) fn only_value(result: &NodeCallResult, output: usize) -> Value {
    let all = values(&result.outputs[output]);
    assert_eq!(all.len(), 1, "expected one item, got {all:?}");
    all.into_iter()
        .next()
        .flatten()
        .unwrap_or_else(|| panic!("output {output} is null; messages: {:?}", result.messages))
}

/// Whether output `output` holds exactly one item and it is null.
pub(crate) fn is_null(result: &NodeCallResult, output: usize) -> bool {
    let all = values(&result.outputs[output]);
    all.len() == 1 && all[0].is_none()
}

/// The texts of the messages of one level.
pub(crate) fn messages(result: &NodeCallResult, level: Level) -> Vec<String> {
    result
        .messages
        .iter()
        .filter(|m| m.level == level)
        .map(|m| m.text.clone())
        .collect()
}

/// The one error message of a call (panics when there is not exactly one).
pub(crate) fn single_error(result: &NodeCallResult) -> String {
    let errors = messages(result, Level::Error);
    assert_eq!(
        errors.len(),
        1,
        "expected one error, got {:?}",
        result.messages
    );
    errors[0].clone()
}

/// Asserts that the call reported exactly one error and that it contains `part`.
pub(crate) fn assert_error(result: &NodeCallResult, part: &str) {
    let error = single_error(result);
    assert!(
        error.contains(part),
        "error {error:?} does not mention {part:?}"
    );
}

/// Asserts that the call reported no message at all.
pub(crate) fn assert_clean(result: &NodeCallResult) {
    assert!(
        result.messages.is_empty(),
        "unexpected messages: {:?}",
        result.messages
    );
}
