//! The repository's rules, checked by `cargo test` (see `tests/tidy.rs`): the crate layering
//! that keeps the engines side by side, no `#[ignore]` or `#[should_panic]` tests, and a reason
//! comment beside every `#[allow(...)]`. This crate has no code of its own.
