//! Every document and section the code and docs cite exists.
//!
//! Comments and docs cite the reference documents by section, as `DESIGN.md "Sphere tree"` or
//! `docs/PROTOCOL.md, "Recorded sessions"`, and link or name them by path (`docs/BENCHMARKS.md`,
//! `[the protocol](docs/PROTOCOL.md#limits)`). A citation of a section that was renamed or never
//! written sends the reader nowhere, so this test reads the repository's sources and documents and
//! checks each one:
//!
//! - a section citation, a document's name (bare or in backticks) then a heading in double
//!   quotes (a comma, and the word `section` or a `§`, may come between; the quoted heading may
//!   wrap onto the next comment line), names a file that exists and a heading of it whose text,
//!   after the leading `#`s, is the quoted text (ignoring case and runs of white space), either
//!   whole or without a trailing parenthetical (`Recorded sessions` cites `## Recorded sessions
//!   (`--record FILE`)`). A bare name (`DESIGN.md`) is the file of that name in `docs/`, else
//!   beside the citing file, else at the top of the repository;
//! - a numbered section citation, a document's name then `§N` or `section N` (`N.M` for the M-th
//!   subsection of the N-th), names a file with that many `##` sections (and `###` under it);
//! - a path into `docs/` ending in `.md`, named anywhere, is a file, from the top of the
//!   repository; so is a bare upper-case name such as `BENCHMARKS.md`;
//! - a Markdown link to a `.md` file, relative to the linking file, is a file, and its `#anchor`
//!   (or an in-page `#anchor`) is the anchor of one of its headings.
//!
//! Sources are the Rust, TypeScript and JavaScript (`*.mjs`), Markdown, protobuf, TOML and shell
//! files (`*.sh`, `*.sbatch`, and scripts without an ending that start with `#!`) outside build
//! output, dependencies and generated code. Separately, no file of the repository points outside
//! it: not at a directory beside the checkout, nor by a relative path that climbs above the top.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

/// The top of the repository.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the tests crate is one level below the top")
        .to_path_buf()
}

/// Directories skipped wherever they are: build output, dependencies, version control.
const SKIP_NAMES: [&str; 3] = ["target", "node_modules", ".git"];

/// Directories (from the top) of generated or ignored output, never read.
const SKIP_ALWAYS: [&str; 4] = [
    "results",
    "fuzz/corpus",
    "fuzz/artifacts",
    "web/test/.build",
];

/// Directories (from the top) of generated code, not read for citations: the viewer's bundle and
/// the code generated from the protocol.
const SKIP_FOR_CITATIONS: [&str; 2] = ["web/dist", "web/src/gen"];

/// File endings read for citations.
const CITING: [&str; 8] = ["rs", "ts", "mjs", "md", "proto", "toml", "sh", "sbatch"];

/// Whether the file at `rel` (from the top) is read for citations: one of the [`CITING`]
/// endings, or a script without an ending (`.ci/run`).
fn is_citing(root: &Path, rel: &Path) -> bool {
    if SKIP_FOR_CITATIONS.iter().any(|s| rel.starts_with(s)) {
        return false;
    }
    match rel.extension() {
        Some(e) => CITING.iter().any(|c| e == *c),
        None => fs::read(root.join(rel)).is_ok_and(|b| b.starts_with(b"#!")),
    }
}

/// Every file under `dir`, as paths relative to `root`, skipping [`SKIP_NAMES`] and
/// [`SKIP_ALWAYS`].
fn walk(root: &Path, dir: &Path, out: &mut Vec<PathBuf>) {
    let entries = fs::read_dir(dir).unwrap_or_else(|e| panic!("read {}: {e}", dir.display()));
    for entry in entries {
        let entry = entry.expect("a directory entry");
        let path = entry.path();
        let rel = path
            .strip_prefix(root)
            .expect("under the root")
            .to_path_buf();
        let name = entry.file_name();
        if SKIP_NAMES.iter().any(|s| name == *s) || SKIP_ALWAYS.iter().any(|s| rel == Path::new(s))
        {
            continue;
        }
        let kind = entry.file_type().expect("a file type");
        if kind.is_dir() {
            walk(root, &path, out);
        } else if kind.is_file() {
            out.push(rel);
        }
    }
}

fn files() -> Vec<PathBuf> {
    let root = root();
    let mut out = Vec::new();
    walk(&root, &root, &mut out);
    out.sort();
    out
}

/// The headings of a Markdown document: their text after the `#`s.
fn headings(markdown: &str) -> Vec<String> {
    leveled_headings(markdown)
        .into_iter()
        .map(|(_, text)| text)
        .collect()
}

/// The headings of a Markdown document: each one's level (its number of `#`s) and text.
fn leveled_headings(markdown: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut fence: Option<&str> = None;
    for line in markdown.lines() {
        let t = line.trim_start();
        if let Some(f) = fence {
            if t.starts_with(f) {
                fence = None;
            }
            continue;
        }
        if t.starts_with("```") || t.starts_with("~~~") {
            fence = Some(&t[..3]);
            continue;
        }
        // A heading starts at the line's start (up to three spaces) with 1-6 `#` and a space.
        if line.len() - t.len() > 3 {
            continue;
        }
        let hashes = t.bytes().take_while(|&b| b == b'#').count();
        if (1..=6).contains(&hashes) && t[hashes..].starts_with([' ', '\t']) {
            let text = t[hashes..].trim().trim_end_matches('#').trim_end();
            out.push((hashes, text.to_string()));
        }
    }
    out
}

/// Whether `markdown` has section `number`: `N`, the N-th `##` heading, or `N.M`, the M-th `###`
/// heading after it (before the next `##`), counting from 1.
fn has_numbered_section(markdown: &str, number: &str) -> bool {
    let parts: Vec<usize> = number.split('.').map_while(|p| p.parse().ok()).collect();
    let (Some(&n), rest) = (parts.first(), parts.get(1..).unwrap_or_default()) else {
        return false;
    };
    if n == 0 || rest.len() > 1 || rest.first() == Some(&0) {
        return false;
    }
    let levels: Vec<usize> = leveled_headings(markdown)
        .into_iter()
        .map(|(level, _)| level)
        .collect();
    let Some(at) = levels
        .iter()
        .enumerate()
        .filter(|(_, l)| **l == 2)
        .nth(n - 1)
        .map(|(i, _)| i)
    else {
        return false;
    };
    match rest.first() {
        None => true,
        Some(&m) => {
            levels[at + 1..]
                .iter()
                .take_while(|l| **l > 2)
                .filter(|l| **l == 3)
                .count()
                >= m
        }
    }
}

/// Lower case, runs of white space as one space.
fn normalise(s: &str) -> String {
    s.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .to_lowercase()
}

/// Whether `heading` is cited by `cited`: the same text, or the same once a trailing
/// parenthetical is dropped from the heading.
fn heading_matches(heading: &str, cited: &str) -> bool {
    let (h, c) = (normalise(heading), normalise(cited));
    if h == c {
        return true;
    }
    h.ends_with(')') && h.rfind(" (").is_some_and(|open| h[..open].trim_end() == c)
}

/// The anchors of `markdown`'s headings, as GitHub makes them: lower case, every character but
/// letters, digits, `-`, `_` and spaces dropped, spaces as `-`; a repeated anchor gets `-1`,
/// `-2`, ...
fn anchors(markdown: &str) -> Vec<String> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    headings(markdown)
        .iter()
        .map(|h| {
            let base: String = h
                .to_lowercase()
                .chars()
                .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
                .map(|c| if c == ' ' { '-' } else { c })
                .collect();
            let n = seen.entry(base.clone()).or_insert(0);
            let anchor = if *n == 0 {
                base.clone()
            } else {
                format!("{base}-{n}")
            };
            *n += 1;
            anchor
        })
        .collect()
}

/// Characters that may make up a path.
fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '/')
}

/// Skip white space after a cited name, across line breaks and the comment markers that start
/// a continued comment line. Returns the new position and whether any white space was skipped.
fn skip_gap(text: &str, mut pos: usize) -> (usize, bool) {
    let start = pos;
    loop {
        let rest = &text[pos..];
        let trimmed = rest.trim_start_matches([' ', '\t']);
        pos += rest.len() - trimmed.len();
        if let Some(after) = trimmed.strip_prefix('\n') {
            pos += 1;
            let line = after.trim_start_matches([' ', '\t']);
            pos += after.len() - line.len();
            for marker in ["//!", "///", "//", "* ", "*\n"] {
                if line.starts_with(marker) {
                    pos += marker.trim_end().len();
                    break;
                }
            }
            continue;
        }
        return (pos, pos > start);
    }
}

/// The text of a quoted heading starting at `open` (the opening quote), its continuation lines'
/// comment markers removed; None if no closing quote comes within a few lines.
fn quoted(text: &str, open: usize) -> Option<String> {
    let body = &text[open + 1..];
    let close = body.find('"')?;
    let raw = &body[..close];
    if raw.len() > 240 || raw.lines().count() > 3 {
        return None;
    }
    let mut out = String::new();
    for (i, line) in raw.lines().enumerate() {
        let mut l = line.trim();
        if i > 0 {
            for marker in ["//!", "///", "//", "*"] {
                if let Some(r) = l.strip_prefix(marker) {
                    l = r.trim_start();
                    break;
                }
            }
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(l);
    }
    Some(out)
}

/// A document named `name` by the file `from`: a path with a `/` from the top; a bare name in
/// `docs/`, else beside `from`, else at the top.
fn resolve_named(root: &Path, from: &Path, name: &str) -> Option<PathBuf> {
    let candidates: Vec<PathBuf> = if name.contains('/') {
        vec![root.join(name.trim_start_matches("./"))]
    } else {
        let beside = from
            .parent()
            .map_or_else(|| root.to_path_buf(), |p| root.join(p));
        vec![
            root.join("docs").join(name),
            beside.join(name),
            root.join(name),
        ]
    };
    candidates.into_iter().find(|p| p.is_file())
}

/// The problems of one file's citations.
fn problems_in(root: &Path, rel: &Path, text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let at = |pos: usize| text[..pos].matches('\n').count() + 1;
    let here = |pos: usize| format!("{}:{}", rel.display(), at(pos));
    let mut docs: HashMap<PathBuf, String> = HashMap::new();
    let mut read = |path: &Path| -> String {
        docs.entry(path.to_path_buf())
            .or_insert_with(|| fs::read_to_string(path).unwrap_or_default())
            .clone()
    };

    // Section citations and named documents: every name ending in `.md`.
    let mut search = 0;
    while let Some(found) = text[search..].find(".md") {
        let end = search + found + 3;
        search = end;
        if text[end..]
            .chars()
            .next()
            .is_some_and(|c| c.is_ascii_alphanumeric())
        {
            continue;
        }
        let start = text[..end - 3]
            .rfind(|c: char| !is_path_char(c))
            .map_or(0, |i| i + 1);
        let name = &text[start..end];
        if name.len() <= 3
            || name.contains("://")
            || name.starts_with('.') && !name.starts_with("./")
        {
            continue;
        }
        let before = text[..start].chars().next_back();
        // A link target is checked as a link (relative to the file) below.
        let in_link = before == Some('(') && text[..start].ends_with("](");
        let is_docs_path = name.starts_with("docs/");
        let mut pos = end;
        if before == Some('`') && text[pos..].starts_with('`') {
            pos += 1;
        }
        if text[pos..].starts_with(',') {
            pos += 1;
        }
        let (mut pos, mut spaced) = skip_gap(text, pos);
        // `section "Heading"`, `§ "Heading"`, `section 3`, `§3.2`.
        let mut number = None;
        for word in ["section", "§"] {
            if spaced && text[pos..].starts_with(word) {
                let (after, gap) = skip_gap(text, pos + word.len());
                let digits = text[after..]
                    .find(|c: char| !(c.is_ascii_digit() || c == '.'))
                    .map_or(text.len() - after, |n| n);
                let n = text[after..after + digits].trim_end_matches('.');
                if !n.is_empty() && n.starts_with(|c: char| c.is_ascii_digit()) {
                    number = Some(n.to_string());
                } else if gap && text[after..].starts_with('"') {
                    (pos, spaced) = (after, true);
                }
                break;
            }
        }
        let cited = (number.is_none() && spaced && text[pos..].starts_with('"'))
            .then(|| quoted(text, pos))
            .flatten();
        let is_reference_doc = !name.contains('/')
            && name[..name.len() - 3]
                .chars()
                .all(|c| c.is_ascii_uppercase() || c == '_');
        if cited.is_none() && number.is_none() && !is_docs_path && !is_reference_doc {
            continue;
        }
        if in_link && cited.is_none() && number.is_none() {
            continue;
        }
        let Some(path) = resolve_named(root, rel, name) else {
            out.push(format!("{}: `{name}` does not exist", here(start)));
            continue;
        };
        if let Some(heading) = cited {
            let doc = read(&path);
            if !headings(&doc).iter().any(|h| heading_matches(h, &heading)) {
                out.push(format!(
                    "{}: `{name}` has no heading \"{heading}\"",
                    here(start)
                ));
            }
        }
        if let Some(number) = number
            && !has_numbered_section(&read(&path), &number)
        {
            out.push(format!("{}: `{name}` has no section {number}", here(start)));
        }
    }

    // Markdown links to Markdown files and to in-page anchors.
    if rel.extension().is_some_and(|e| e == "md") {
        let mut search = 0;
        while let Some(found) = text[search..].find("](") {
            let open = search + found + 2;
            search = open;
            let Some(close) = text[open..].find(')') else {
                continue;
            };
            let target = text[open..open + close].trim();
            let target = target.split_whitespace().next().unwrap_or("");
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, anchor) = match target.split_once('#') {
                Some((f, a)) => (f, Some(a)),
                None => (target, None),
            };
            let path = if file.is_empty() {
                root.join(rel)
            } else if file.ends_with(".md") {
                let dir = rel
                    .parent()
                    .map_or_else(|| root.to_path_buf(), |p| root.join(p));
                let path = dir.join(file);
                if !path.is_file() {
                    out.push(format!(
                        "{}: link to `{file}`, which does not exist",
                        here(open)
                    ));
                    continue;
                }
                path
            } else {
                continue;
            };
            if let Some(anchor) = anchor {
                let doc = read(&path);
                if !anchors(&doc).iter().any(|a| a == anchor) {
                    out.push(format!(
                        "{}: link to `{target}`: no heading has the anchor `#{anchor}`",
                        here(open)
                    ));
                }
            }
        }
    }
    out
}

#[test]
fn every_cited_document_and_section_exists() {
    let root = root();
    let mut problems = Vec::new();
    let mut citing = 0;
    for rel in files() {
        if !is_citing(&root, &rel) {
            continue;
        }
        let text = fs::read_to_string(root.join(&rel))
            .unwrap_or_else(|e| panic!("read {}: {e}", rel.display()));
        citing += 1;
        problems.extend(problems_in(&root, &rel, &text));
    }
    assert!(
        citing > 100,
        "only {citing} source files found under {}",
        root.display()
    );
    assert!(
        problems.is_empty(),
        "citations of documents or sections that do not exist:\n{}",
        problems.join("\n")
    );
}

/// The checker itself finds what it is for, on a file that is not in the repository.
#[test]
fn a_bogus_citation_is_caught() {
    let root = root();
    let rel = Path::new("server/src/example.rs");
    let ok = "//! See DESIGN.md \"Sphere tree\" and docs/DESIGN.md, \"Exact\n//! answer\".\n";
    assert_eq!(problems_in(&root, rel, ok), Vec::<String>::new());
    // Built here, so that this file does not name a missing document itself.
    let nowhere = format!("/// See docs/{}.md for more.\n", "NOWHERE");
    let also_ok = "// `docs/DESIGN.md` \"Scene\", DESIGN.md section \"Shape\", DESIGN.md §1, DESIGN.md section 2.\n";
    assert_eq!(problems_in(&root, rel, also_ok), Vec::<String>::new());
    for bad in [
        "//! DESIGN.md \"No such section\"\n",
        "//! docs/DESIGN.md \"Sphere\"\n",
        nowhere.as_str(),
        "/// PROTOCOL.md \"Limits of the universe\"\n",
        "// see `docs/DESIGN.md` \"No such section\"\n",
        "// DESIGN.md section \"No such section\"\n",
        concat!("// DESIGN.md §", "99\n"),
        concat!("// BENCHMARKS.md sec", "tion 1.99\n"),
    ] {
        let found = problems_in(&root, rel, bad);
        assert_eq!(found.len(), 1, "{bad:?}: {found:?}");
    }
    // A Markdown file in docs/ that does not exist (named so that this file does not cite it).
    let md = PathBuf::from(format!("docs/{}.md", "EXAMPLE"));
    let links =
        "[a](PROTOCOL.md#limits), [b](#nowhere), [c](BENCHMARKS.md#no-such-anchor), [d](GONE.md)\n";
    let found = problems_in(&root, &md, links);
    assert_eq!(found.len(), 3, "{found:?}");
    // Scripts and web tests are read too: a shell script without an ending, an `.mjs` test.
    assert!(is_citing(&root, Path::new(".ci/run")));
    assert!(is_citing(&root, Path::new("web/test/contact.test.mjs")));
    assert!(!is_citing(&root, Path::new("web/dist/index.html")));
    let script = "#!/bin/sh\n# the figures: DESIGN.md \"No such section\"\n";
    assert_eq!(
        problems_in(&root, Path::new("deploy/x.sh"), script).len(),
        1
    );
}

#[test]
fn numbered_sections_count_headings() {
    let doc = "# T\n## A\n### A1\n### A2\n## B\n```\n## not a heading\n```\n";
    assert!(has_numbered_section(doc, "1"));
    assert!(has_numbered_section(doc, "2"));
    assert!(!has_numbered_section(doc, "3"));
    assert!(has_numbered_section(doc, "1.2"));
    assert!(!has_numbered_section(doc, "1.3"));
    assert!(!has_numbered_section(doc, "2.1"));
    assert!(!has_numbered_section(doc, "0"));
}

#[test]
fn headings_are_matched_as_documented() {
    assert!(heading_matches(
        "Recorded sessions (`--record FILE`)",
        "recorded sessions"
    ));
    assert!(heading_matches(
        "Walls reflect the normal velocity component",
        "walls reflect the normal velocity component"
    ));
    assert!(!heading_matches("Sphere tree", "Sphere"));
    let doc = "# T\n```sh\n# not a heading\n```\n## The study (`a`, b)\n## Again\n## Again\n";
    assert_eq!(headings(doc), ["T", "The study (`a`, b)", "Again", "Again"]);
    assert_eq!(anchors(doc), ["t", "the-study-a-b", "again", "again-1"]);
}

/// The relative paths in `text` (of the file at `rel`) that climb above the top of the
/// repository: a run of `../` starting a path, resolved from the file's directory.
fn paths_outside(rel: &Path, text: &str) -> Vec<String> {
    let depth = rel.components().count().saturating_sub(1);
    let mut out = Vec::new();
    let mut search = 0;
    while let Some(found) = text[search..].find("../") {
        let start = search + found;
        search = start + 3;
        if text[..start].chars().next_back().is_some_and(is_path_char) {
            continue;
        }
        let end = text[start..]
            .find(|c: char| !is_path_char(c))
            .map_or(text.len(), |n| start + n);
        let path = &text[start..end];
        search = end.max(search);
        // Walk the path's components from the file's directory; climbing past the top is out.
        let mut level = depth as isize;
        let mut escapes = false;
        for part in path.split('/') {
            match part {
                ".." => level -= 1,
                "" | "." => {}
                _ => level += 1,
            }
            escapes |= level < 0;
        }
        if escapes {
            out.push(path.to_string());
        }
    }
    out
}

/// Nothing points outside the repository: a user's clone has only the repository, so no file
/// names a directory beside the checkout or a relative path that climbs above the top.
#[test]
fn nothing_points_outside_the_repository() {
    let root = root();
    let needle = concat!("..", "/shared").as_bytes();
    let mut offending = Vec::new();
    for rel in files() {
        let bytes = fs::read(root.join(&rel)).unwrap_or_default();
        if bytes.windows(needle.len()).any(|w| w == needle) {
            offending.push(format!(
                "{}: names a directory beside the checkout",
                rel.display()
            ));
        }
        if let Ok(text) = std::str::from_utf8(&bytes) {
            for path in paths_outside(&rel, text) {
                offending.push(format!("{}: `{path}` climbs above the top", rel.display()));
            }
        }
    }
    assert!(
        offending.is_empty(),
        "files pointing outside the repository:\n{}",
        offending.join("\n")
    );
}

#[test]
fn a_path_above_the_top_is_caught() {
    let at = |rel: &str, text: &str| paths_outside(Path::new(rel), text);
    assert_eq!(
        at(
            "guide/notebook/a.md",
            "[b](../BENCHMARKS.md), ../../README.md"
        ),
        Vec::<String>::new()
    );
    assert_eq!(
        at("server/engine/Cargo.toml", "path = \"../../proto\""),
        Vec::<String>::new()
    );
    assert_eq!(
        at("guide/a.md", "see ../../elsewhere/data"),
        ["../../elsewhere/data"]
    );
    assert_eq!(at("README.md", "cd ../sibling && make"), ["../sibling"]);
    let climbing = concat!("../x/../../", "../y");
    assert_eq!(at("a/b/c.rs", climbing), [climbing]);
}
