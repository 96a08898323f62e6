//! Hashes the sources that compute a study's cells (the engine, the gaze crate and this bench) into
//! `FOVEAL_ENGINE_SOURCE_HASH`: a sharded run's partials carry it, and a merge refuses partials
//! computed by different sources, which could disagree on a cell.

use std::path::{Path, PathBuf};

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in rd.flatten() {
        let p = entry.path();
        if p.is_dir() {
            files(&p, out);
        } else {
            out.push(p);
        }
    }
}

fn main() {
    let here = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let roots = [
        ("engine", here.join("../engine/src")),
        ("gaze", here.join("../../client/gaze/src")),
        ("bench", here.join("src")),
    ];
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for &b in bytes {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    };
    for (name, root) in &roots {
        println!("cargo:rerun-if-changed={}", root.display());
        let mut fs = Vec::new();
        files(root, &mut fs);
        fs.sort();
        for f in fs {
            let rel = f.strip_prefix(root).unwrap_or(&f);
            eat(name.as_bytes());
            eat(rel.to_string_lossy().as_bytes());
            eat(&[0]);
            eat(&std::fs::read(&f).unwrap_or_default());
            eat(&[0]);
        }
    }
    println!("cargo:rustc-env=FOVEAL_ENGINE_SOURCE_HASH={h:016x}");
}
