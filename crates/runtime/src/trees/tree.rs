//! Data trees: ordered branches of typed items, addressed by [`TreePath`]s.

use std::fmt;

use crate::{Column, DataType, Item, TreePath, Value};

/// One list of a data tree: typed, contiguous items plus a mask of null items.
///
/// Null items hold a placeholder in the column; [`Branch::is_null`] tells them apart.
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    items: Column,
    /// Empty when no item is null; otherwise one flag per item.
    nulls: Vec<bool>,
}

impl Branch {
    /// An empty branch of the given type.
    pub fn new(data_type: DataType) -> Self {
        Self {
            items: Column::new(data_type),
            nulls: Vec::new(),
        }
    }

    /// A branch holding a column of items, none of them null.
    pub fn from_column(items: Column) -> Self {
        Self {
            items,
            nulls: Vec::new(),
        }
    }

    /// A branch of typed items, none of them null.
    pub fn from_items<T: Item>(items: Vec<T>) -> Self {
        Self::from_column(T::into_column(items))
    }

    /// A branch from a column and a null mask (one flag per item, or empty for none).
    ///
    /// A mask of the wrong length is ignored, keeping every item.
    pub fn from_parts(items: Column, nulls: Vec<bool>) -> Self {
        let mut b = Self { items, nulls };
        if b.nulls.len() != b.items.len() || !b.nulls.iter().any(|&n| n) {
            b.nulls = Vec::new();
        }
        b
    }

    /// The column of items (null items hold placeholders).
    pub fn column(&self) -> &Column {
        &self.items
    }

    /// The null mask: empty when no item is null, else one flag per item.
    pub fn null_mask(&self) -> &[bool] {
        &self.nulls
    }

    /// The column and null mask, consuming the branch.
    pub fn into_parts(self) -> (Column, Vec<bool>) {
        (self.items, self.nulls)
    }

    /// The type of the column.
    pub fn data_type(&self) -> DataType {
        self.items.data_type()
    }

    /// The number of items, null items included.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// Whether the branch has no items.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Whether the item at `index` is null (or past the end).
    #[inline]
    pub fn is_null(&self, index: usize) -> bool {
        index >= self.items.len() || (!self.nulls.is_empty() && self.nulls[index])
    }

    /// Whether any item is null.
    pub fn has_nulls(&self) -> bool {
        !self.nulls.is_empty()
    }

    /// The typed items, if the column is of type `T` (null items hold placeholders).
    #[inline]
    pub fn slice<T: Item>(&self) -> Option<&[T]> {
        T::slice(&self.items)
    }

    /// The typed item at `index`, or `None` when it is null, past the end or of another type.
    #[inline]
    pub fn get<T: Item>(&self, index: usize) -> Option<&T> {
        if self.is_null(index) {
            return None;
        }
        T::slice(&self.items).map(|s| &s[index])
    }

    /// The item at `index` as a [`Value`], or `None` when it is null or past the end.
    pub fn value(&self, index: usize) -> Option<Value> {
        if self.is_null(index) {
            None
        } else {
            self.items.value(index)
        }
    }

    /// Appends an item.
    pub fn push_value(&mut self, value: Value) {
        self.items.push_value(value);
        if !self.nulls.is_empty() {
            self.nulls.push(false);
        }
    }

    /// Appends an item, or a null for `None`.
    pub fn push_option(&mut self, value: Option<Value>) {
        match value {
            Some(v) => self.push_value(v),
            None => self.push_null(),
        }
    }

    /// Appends a typed item. An item of another type than the column turns it generic.
    #[inline]
    pub fn push<T: Item>(&mut self, item: T) {
        match T::vec_mut(&mut self.items) {
            Some(v) => v.push(item),
            None => self.items.push_value(item.into_value()),
        }
        if !self.nulls.is_empty() {
            self.nulls.push(false);
        }
    }

    /// Appends a null item.
    pub fn push_null(&mut self) {
        if self.nulls.is_empty() {
            self.nulls = vec![false; self.items.len()];
        }
        self.items.push_placeholder();
        self.nulls.push(true);
    }

    /// Appends every item of `other` (a column of another type turns this one generic).
    pub fn extend(&mut self, other: &Branch) {
        self.extend_range(other, 0..other.len());
    }

    /// Appends the items `range` of `other`.
    pub fn extend_range(&mut self, other: &Branch, range: std::ops::Range<usize>) {
        if self.items.is_empty() && self.nulls.is_empty() && self.data_type() != other.data_type() {
            self.items = Column::new(other.data_type());
        }
        let before = self.items.len();
        self.items.extend_from(&other.items, range.clone());
        if other.has_nulls() || self.has_nulls() {
            let had_nulls = self.has_nulls();
            if !had_nulls {
                self.nulls = vec![false; before];
            }
            for i in range {
                self.nulls.push(other.is_null(i));
            }
            // A non-empty mask holds a null, so only the appended part needs a look.
            if !had_nulls && !self.nulls[before..].iter().any(|&n| n) {
                self.nulls.clear();
            }
        }
    }

    /// Reverses the order of the items.
    pub fn reverse(&mut self) {
        self.items.reverse();
        self.nulls.reverse();
    }

    /// The items as values, `None` for nulls.
    pub fn values(&self) -> impl Iterator<Item = Option<Value>> + '_ {
        (0..self.len()).map(|i| self.value(i))
    }

    /// The branch with a typed column when it is generic but its items (nulls aside) are all
    /// of one type: the same items and nulls, stored contiguously. Other branches, and
    /// generic ones of mixed items or only nulls, are returned as they are.
    pub fn narrowed(self) -> Branch {
        let items = self.items.narrowed(&self.nulls);
        Branch {
            items,
            nulls: self.nulls,
        }
    }
}

/// A Grasshopper data tree: branches of items, each at a unique [`TreePath`], kept sorted by
/// path. Branches may be empty and items may be null.
///
/// A single item is a tree with one branch `{0}` holding one item; a list is a tree with one
/// branch.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DataTree {
    branches: Vec<(TreePath, Branch)>,
}

impl DataTree {
    /// A tree with no branches.
    pub fn new() -> Self {
        Self::default()
    }

    /// A tree holding one item on `{0}`.
    pub fn from_item<T: Item>(item: T) -> Self {
        Self::from_list(vec![item])
    }

    /// A tree holding one list on `{0}`.
    pub fn from_list<T: Item>(items: Vec<T>) -> Self {
        let mut t = Self::new();
        t.insert(TreePath::zero(), Branch::from_items(items));
        t
    }

    /// A tree holding one value on `{0}`.
    pub fn from_value(value: Value) -> Self {
        let mut b = Branch::new(value.data_type());
        b.push_value(value);
        let mut t = Self::new();
        t.insert(TreePath::zero(), b);
        t
    }

    /// The number of branches.
    pub fn branch_count(&self) -> usize {
        self.branches.len()
    }

    /// The total number of items in all branches, nulls included.
    pub fn item_count(&self) -> usize {
        self.branches.iter().map(|(_, b)| b.len()).sum()
    }

    /// Whether the tree has no branches.
    pub fn is_empty(&self) -> bool {
        self.branches.is_empty()
    }

    /// Whether the tree has no items at all (no branches, or only empty ones).
    pub fn has_no_items(&self) -> bool {
        self.branches.iter().all(|(_, b)| b.is_empty())
    }

    /// The branches in path order.
    pub fn branches(&self) -> &[(TreePath, Branch)] {
        &self.branches
    }

    /// The paths in order.
    pub fn paths(&self) -> impl Iterator<Item = &TreePath> {
        self.branches.iter().map(|(p, _)| p)
    }

    /// The branch at `path`.
    pub fn branch(&self, path: &TreePath) -> Option<&Branch> {
        self.position(path).ok().map(|i| &self.branches[i].1)
    }

    /// The branch at `path`, mutably.
    pub fn branch_mut(&mut self, path: &TreePath) -> Option<&mut Branch> {
        match self.position(path) {
            Ok(i) => Some(&mut self.branches[i].1),
            Err(_) => None,
        }
    }

    /// The branch at `path`, created empty with type `data_type` if missing.
    pub fn branch_or_insert(&mut self, path: TreePath, data_type: DataType) -> &mut Branch {
        let i = match self.position(&path) {
            Ok(i) => i,
            Err(i) => {
                self.branches.insert(i, (path, Branch::new(data_type)));
                i
            }
        };
        &mut self.branches[i].1
    }

    /// Whether the tree has a branch at `path`.
    pub fn contains_path(&self, path: &TreePath) -> bool {
        self.position(path).is_ok()
    }

    /// Puts `branch` at `path`, replacing any branch there.
    pub fn insert(&mut self, path: TreePath, branch: Branch) {
        match self.position(&path) {
            Ok(i) => self.branches[i].1 = branch,
            Err(i) => self.branches.insert(i, (path, branch)),
        }
    }

    /// Appends the items of `branch` to the branch at `path` (created if missing).
    pub fn append(&mut self, path: TreePath, branch: &Branch) {
        match self.position(&path) {
            Ok(i) => self.branches[i].1.extend(branch),
            Err(i) => self.branches.insert(i, (path, branch.clone())),
        }
    }

    /// Merges `other` into this tree: branches at new paths are added, items of branches at
    /// existing paths are appended (Grasshopper's merge of several wires into one input).
    pub fn merge(&mut self, other: &DataTree) {
        if self.branches.is_empty() {
            self.branches = other.branches.clone();
            return;
        }
        for (path, branch) in &other.branches {
            self.append(path.clone(), branch);
        }
    }

    /// Builds a tree from branches in any order; branches at equal paths are concatenated
    /// in the order given.
    pub fn from_branches(branches: impl IntoIterator<Item = (TreePath, Branch)>) -> Self {
        let mut v: Vec<(TreePath, Branch)> = branches.into_iter().collect();
        if v.windows(2).all(|w| w[0].0 < w[1].0) {
            return Self { branches: v };
        }
        // Stable sort keeps the order of equal paths.
        v.sort_by(|a, b| a.0.cmp(&b.0));
        let mut out: Vec<(TreePath, Branch)> = Vec::with_capacity(v.len());
        for (path, branch) in v {
            match out.last_mut() {
                Some((last, b)) if *last == path => b.extend(&branch),
                _ => out.push((path, branch)),
            }
        }
        Self { branches: out }
    }

    /// The tree with every branch [narrowed](Branch::narrowed).
    pub fn narrowed(self) -> DataTree {
        Self {
            branches: self
                .branches
                .into_iter()
                .map(|(path, branch)| (path, branch.narrowed()))
                .collect(),
        }
    }

    /// The branches, consuming the tree.
    pub fn into_branches(self) -> Vec<(TreePath, Branch)> {
        self.branches
    }

    /// The single common type of all branches, or `Generic` when they differ.
    pub fn data_type(&self) -> DataType {
        let mut types = self
            .branches
            .iter()
            .filter(|(_, b)| !b.is_empty())
            .map(|(_, b)| b.data_type());
        match types.next() {
            None => DataType::Generic,
            Some(first) if types.all(|t| t == first) => first,
            Some(_) => DataType::Generic,
        }
    }

    /// All items in path order, `None` for nulls.
    pub fn values(&self) -> impl Iterator<Item = Option<Value>> + '_ {
        self.branches.iter().flat_map(|(_, b)| b.values())
    }

    fn position(&self, path: &TreePath) -> Result<usize, usize> {
        self.branches.binary_search_by(|(p, _)| p.cmp(path))
    }
}

impl fmt::Display for DataTree {
    /// Prints each branch as `{0;1}` followed by its items, one per line, `null` for nulls.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (path, branch) in &self.branches {
            writeln!(f, "{path} ({} items)", branch.len())?;
            for (i, v) in branch.values().enumerate() {
                match v {
                    Some(v) => writeln!(f, "  [{i}] {v:?}")?,
                    None => writeln!(f, "  [{i}] null")?,
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generic_branches_of_one_type_narrow_to_typed_columns() {
        let mut b = Branch::new(DataType::Generic);
        b.push_value(Value::Integer(4));
        b.push_null();
        b.push_value(Value::Integer(-1));
        let values: Vec<Option<Value>> = b.values().collect();
        let narrow = b.clone().narrowed();
        assert_eq!(narrow.data_type(), DataType::Integer);
        assert_eq!(narrow.slice::<i64>().map(<[i64]>::len), Some(3));
        assert_eq!(narrow.null_mask(), [false, true, false]);
        assert_eq!(narrow.values().collect::<Vec<_>>(), values);
        // Mixed items, only nulls, and typed branches are left as they are.
        b.push_value(Value::Number(1.0));
        assert_eq!(b.clone().narrowed(), b);
        let mut nulls = Branch::new(DataType::Generic);
        nulls.push_null();
        assert_eq!(nulls.clone().narrowed(), nulls);
        let typed = Branch::from_items(vec![1.0, 2.0]);
        assert_eq!(typed.clone().narrowed(), typed);
    }

    #[test]
    fn branches_stay_sorted_and_unique() {
        let mut t = DataTree::new();
        t.insert(TreePath::from([1]), Branch::from_items(vec![1.0]));
        t.insert(TreePath::from([0, 1]), Branch::from_items(vec![2.0]));
        t.append(TreePath::from([1]), &Branch::from_items(vec![3.0]));
        let paths: Vec<String> = t.paths().map(ToString::to_string).collect();
        assert_eq!(paths, ["{0;1}", "{1}"]);
        assert_eq!(
            t.branch(&TreePath::from([1])).unwrap().slice::<f64>(),
            Some(&[1.0, 3.0][..])
        );
    }

    #[test]
    fn nulls_are_tracked_per_item() {
        let mut b = Branch::new(DataType::Number);
        b.push(1.0);
        b.push_null();
        b.push(3.0);
        assert!(!b.is_null(0));
        assert!(b.is_null(1));
        assert_eq!(b.get::<f64>(2), Some(&3.0));
        assert_eq!(b.get::<f64>(1), None);
        let mut c = Branch::new(DataType::Number);
        c.extend(&b);
        assert_eq!(c, b);
    }

    #[test]
    fn merge_appends_matching_paths() {
        let mut a = DataTree::from_list(vec![1.0, 2.0]);
        let b = DataTree::from_list(vec![3.0]);
        a.merge(&b);
        assert_eq!(
            a.branch(&TreePath::zero()).unwrap().slice::<f64>(),
            Some(&[1.0, 2.0, 3.0][..])
        );
    }
}
