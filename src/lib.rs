//! ccd-exact (placeholder while the crates below it are built).
