//! The benchmark package of ccd-exact: `cargo bench -p ccd-benches` (see
//! `table4.sh` and `docs/table4.md`). The benchmarks are the `[[bench]]`
//! targets beside this file; the library is empty.
