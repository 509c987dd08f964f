//! The node runtime of locus: data trees, typed ports, Grasshopper matching and evaluation.
