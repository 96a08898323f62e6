//! What produced a result: the commit and the hash of the sources that compute a study's cells
//! (the engine, the gaze crate and this bench; [`crate::shard::ENGINE_SOURCE_HASH`]). Every
//! report, CSV and figure of the study carries it, so a figure copied out of its directory still
//! says which engine drew it, and a stale one can be told from a fresh one at a glance
//! (`docs/DESIGN.md`, "Statistics of the study").

use std::process::Command;
use std::sync::OnceLock;

use crate::shard::ENGINE_SOURCE_HASH;

/// The commit and the engine's source hash.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Stamp {
    /// `git rev-parse --short=12 HEAD`, with `-modified` when the sources behind the hash differ
    /// from that commit; `FOVEAL_COMMIT` where set (a build without git); else `unknown`.
    pub commit: String,
    /// [`ENGINE_SOURCE_HASH`] of this build.
    pub engine: &'static str,
}

impl Stamp {
    /// One line for a report or a figure's foot.
    pub fn line(&self) -> String {
        format!(
            "foveal commit {}, engine source hash {}",
            self.commit, self.engine
        )
    }

    /// `csv` with two columns added to every line: `commit` and `engine_hash` (the header's
    /// names, then this stamp's values on every row), so each row read alone still says what
    /// computed it.
    pub fn csv(&self, csv: &str) -> String {
        let mut out = String::with_capacity(csv.len() + 40 * csv.lines().count());
        for (i, line) in csv.lines().enumerate() {
            out.push_str(line);
            if i == 0 {
                out.push_str(",commit,engine_hash\n");
            } else {
                out.push_str(&format!(",{},{}\n", self.commit, self.engine));
            }
        }
        out
    }
}

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

fn commit() -> String {
    if let Ok(c) = std::env::var("FOVEAL_COMMIT")
        && !c.trim().is_empty()
    {
        return c.trim().to_string();
    }
    let Some(head) = git(&["rev-parse", "--short=12", "HEAD"]) else {
        return "unknown".into();
    };
    // The hashed sources (see build.rs) relative to the repository's top.
    let modified = git(&[
        "status",
        "--porcelain",
        "--untracked-files=no",
        "--",
        ":/server/engine/src",
        ":/client/gaze/src",
        ":/server/bench/src",
    ])
    .is_some_and(|s| !s.is_empty());
    if modified {
        format!("{head}-modified")
    } else {
        head
    }
}

/// This process's stamp (git is asked once; `foveal-bench` asks as it starts).
pub fn current() -> &'static Stamp {
    static STAMP: OnceLock<Stamp> = OnceLock::new();
    STAMP.get_or_init(|| Stamp {
        commit: commit(),
        engine: ENGINE_SOURCE_HASH,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_csv_row_carries_the_stamp() {
        let s = Stamp {
            commit: "abc".into(),
            engine: "0123",
        };
        assert_eq!(
            s.csv("a,b\n1,2\n3,4\n"),
            "a,b,commit,engine_hash\n1,2,abc,0123\n3,4,abc,0123\n"
        );
        assert!(s.line().contains("abc") && s.line().contains("0123"));
        assert_eq!(current().engine, ENGINE_SOURCE_HASH);
        assert!(!current().commit.is_empty());
    }
}
