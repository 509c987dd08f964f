//! The node library of locus.
