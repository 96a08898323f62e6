//! No code: this crate only depends on the workspace's shared dependencies with one feature set
//! for every build (see its `Cargo.toml`).
