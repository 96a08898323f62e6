//! The committed study (`docs/study`) against this engine and against its own CSVs: it must have
//! been run by an engine that answers as this one does, and every number quoted from it (its
//! `docs/study/REPORT.md`, the generated blocks of README.md and docs/BENCHMARKS.md) must be what its CSVs
//! give (`docs/DESIGN.md`, "Statistics of the study").

use std::path::{Path, PathBuf};

use foveal_bench::{claims, staleness};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn study() -> PathBuf {
    root().join("docs/study")
}

/// Fails when the engine's deterministic answers (sphere tests, deemed pairs, Δ and P on the tiny
/// protocol) differ from those of the engine that ran the committed study: change a sphere-tree
/// constant and this fails until the study is regenerated.
#[test]
fn the_committed_study_was_run_by_an_engine_that_answers_as_this_one() {
    let committed = staleness::read(&study()).expect("docs/study/stamp.json");
    let now = staleness::fingerprint().expect("fingerprint");
    assert_eq!(
        committed.fingerprint, now,
        "docs/study was generated at commit {} by an engine that answers differently from this \
         one (its fingerprint {}, this engine's {now}): regenerate it with `{}`, then `cargo run \
         --release -p foveal-bench -- study-report docs/study --quote README.md --quote \
         docs/BENCHMARKS.md`",
        committed.commit, committed.fingerprint, committed.command
    );
}

#[test]
fn the_report_and_the_quoted_numbers_are_the_committed_csvs() {
    let dir = study();
    let report = claims::report(&dir).expect("report from the CSVs");
    let committed =
        std::fs::read_to_string(dir.join(claims::REPORT_FILE)).expect("docs/study/REPORT.md");
    assert!(
        report == committed,
        "docs/study/REPORT.md is not what its CSVs give: run `cargo run --release -p \
         foveal-bench -- study-report docs/study --quote README.md --quote docs/BENCHMARKS.md`"
    );
    let block = claims::quote(&dir).expect("quote");
    for file in ["README.md", "docs/BENCHMARKS.md"] {
        let text = std::fs::read_to_string(root().join(file)).expect("readable");
        let quoted = claims::quoted(&text)
            .unwrap_or_else(|| panic!("{file} has no generated block of the study's claims"));
        assert!(
            quoted == block,
            "{file}'s study block differs from the committed CSVs: run `cargo run --release -p \
             foveal-bench -- study-report docs/study --quote README.md --quote \
             docs/BENCHMARKS.md`\n--- quoted\n{quoted}\n--- generated\n{block}"
        );
    }
}

/// The markers' block is replaced whole, and a file without them is refused.
#[test]
fn a_quote_replaces_only_its_block() {
    let text = format!(
        "before\n{}\nold\n{}\nafter\n",
        claims::QUOTE_BEGIN,
        claims::QUOTE_END
    );
    let new = claims::replace_quote(&text, "new\n").expect("markers");
    assert_eq!(claims::quoted(&new), Some("new\n"));
    assert!(new.starts_with("before\n") && new.ends_with("after\n"));
    assert!(claims::replace_quote("no markers", "x").is_none());
}
