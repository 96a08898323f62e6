//! Empty: cargo builds a package's build dependencies only when it has a build script, and this
//! crate's build dependencies are what unify the procedural macros' and build scripts' features.
fn main() {}
