//! Tidy test: the kernel's modules depend on each other in one direction only.
//!
//! The order is read from ARCHITECTURE.md (the line that starts with `Kernel layers`), so the
//! document and the code cannot drift apart. A module may use itself and the layers before it;
//! `crate::` paths in the module's non-test code (before its first `#[cfg(test)]`, and not in a
//! `tests.rs`) are resolved to the layer they live in (through
//! the re-exports of `lib.rs` for paths like `crate::NurbsCurve`). Test modules may use anything.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The layers, lowest first, as `curve::nurbs` style module paths.
fn layers() -> Vec<String> {
    let doc =
        fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../ARCHITECTURE.md"))
            .expect("ARCHITECTURE.md");
    let line = doc
        .lines()
        .find(|l| l.starts_with("Kernel layers"))
        .expect("ARCHITECTURE.md has a line starting with `Kernel layers`");
    let list = line.split_once(':').expect("`Kernel layers …: a → b`").1;
    list.split('→')
        .map(|s| s.trim().trim_matches('`').to_owned())
        .collect()
}

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a file relative to `src/` (`curve/nurbs/batch.rs` → `curve::nurbs::batch`).
fn module_of(file: &Path) -> String {
    let rel = file.strip_prefix(src()).unwrap().with_extension("");
    let parts: Vec<_> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let parts = match parts.last().map(String::as_str) {
        Some("mod") => &parts[..parts.len() - 1],
        _ => &parts[..],
    };
    parts.join("::")
}

/// The code of a file before its first `#[cfg(test)]`, without comments.
fn non_test_code(text: &str) -> String {
    let end = text.find("#[cfg(test)]").unwrap_or(text.len());
    text[..end]
        .lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every path named after `crate::` in `code`, expanding `use crate::{a::b, C}` groups one level.
fn crate_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let item = item.trim();
                if !item.is_empty() {
                    out.push(
                        item.split(|c: char| c == '{' || c.is_whitespace())
                            .next()
                            .unwrap()
                            .to_owned(),
                    );
                }
            }
        } else {
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(rest.len());
            out.push(rest[..end].trim_end_matches(':').to_owned());
        }
    }
    out
}

/// Root names re-exported by lib.rs, mapped to the module path they come from.
fn reexports() -> HashMap<String, String> {
    let lib = fs::read_to_string(src().join("lib.rs")).unwrap();
    let mut map = HashMap::new();
    for statement in non_test_code(&lib).split(';') {
        let Some(path) = statement.trim().strip_prefix("pub use crate::") else {
            continue;
        };
        let (module, names) = match path.split_once("::{") {
            Some((m, names)) => (m.to_owned(), names.trim_end_matches('}').to_owned()),
            None => {
                let (m, name) = path.rsplit_once("::").unwrap();
                (m.to_owned(), name.to_owned())
            }
        };
        for name in names.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            let full = if name == "self" {
                module.clone()
            } else {
                format!("{module}::{name}")
            };
            map.insert(name.to_owned(), full);
        }
    }
    map
}

/// The layer a module path belongs to: the longest layer that is a prefix of it.
fn layer_of<'a>(module: &str, layers: &'a [String]) -> Option<(usize, &'a str)> {
    layers
        .iter()
        .enumerate()
        .filter(|(_, l)| module == l.as_str() || module.starts_with(&format!("{l}::")))
        .max_by_key(|(_, l)| l.len())
        .map(|(i, l)| (i, l.as_str()))
}

#[test]
fn kernel_modules_depend_downward_only() {
    let layers = layers();
    assert!(
        layers.len() >= 6,
        "too few kernel layers read from ARCHITECTURE.md: {layers:?}"
    );
    let reexports = reexports();
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    files.sort();
    let mut problems = Vec::new();
    for file in &files {
        let module = module_of(file);
        // `lib.rs` only re-exports; a `tests.rs` is a test module moved out of its parent.
        if module == "lib" || file.file_name().is_some_and(|n| n == "tests.rs") {
            continue;
        }
        let Some((own, own_name)) = layer_of(&module, &layers) else {
            problems.push(format!(
                "{module}: in no layer of ARCHITECTURE.md's `Kernel layers`"
            ));
            continue;
        };
        let code = non_test_code(&fs::read_to_string(file).unwrap());
        for path in crate_paths(&code) {
            let first = path.split("::").next().unwrap();
            let target = match reexports.get(first) {
                Some(full) => full.clone(),
                None => path.clone(),
            };
            match layer_of(&target, &layers) {
                Some((used, used_name)) if used > own => problems.push(format!(
                    "{module} ({own_name}) uses crate::{path} ({used_name}), a higher layer"
                )),
                Some(_) => {}
                None => problems.push(format!("{module}: cannot place crate::{path}")),
            }
        }
    }
    assert!(
        problems.is_empty(),
        "kernel dependencies against the recorded direction:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_tidy_test_sees_an_upward_dependency() {
    // The checker itself: a lower layer naming a higher one is found.
    let layers: Vec<String> = ["error", "geometry", "curve"].map(String::from).to_vec();
    let paths =
        crate_paths("use crate::{Point3, curve::nurbs::basis};\nlet x = crate::curve::Foo;");
    assert_eq!(paths, ["Point3", "curve::nurbs::basis", "curve::Foo"]);
    assert_eq!(
        layer_of("curve::nurbs::basis", &layers).map(|l| l.0),
        Some(2)
    );
    assert_eq!(layer_of("geometry", &layers).map(|l| l.0), Some(1));
    assert_eq!(layer_of("surface", &layers), None);
}

/// ARCHITECTURE.md's code map names every module folder of every crate (as `name/` or
/// `` `name` ``), so that a new folder cannot appear without its place on the map. A folder
/// holding only `tests.rs` (a module's unit tests moved out of it) is not a module folder.
#[test]
fn code_map_names_every_module_folder() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let mut missing = Vec::new();
    let mut folders = Vec::new();
    for krate in fs::read_dir(root.join("crates")).unwrap() {
        let src = krate.unwrap().path().join("src");
        if src.is_dir() {
            module_folders(&src, &mut folders);
        }
    }
    assert!(
        !folders.is_empty(),
        "no module folders found under crates/*/src"
    );
    for folder in folders {
        let name = folder.file_name().unwrap().to_string_lossy().into_owned();
        if !doc.contains(&format!("{name}/")) && !doc.contains(&format!("`{name}`")) {
            missing.push(folder.display().to_string());
        }
    }
    assert!(
        missing.is_empty(),
        "ARCHITECTURE.md's code map does not name these module folders: {missing:?}"
    );
}

/// Every folder under `dir`, recursively.
fn module_folders(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            // A folder that holds only `tests.rs` is its parent module's unit tests, moved out.
            let only_tests = fs::read_dir(&path)
                .unwrap()
                .all(|e| e.unwrap().file_name() == "tests.rs");
            if !only_tests {
                out.push(path.clone());
            }
            module_folders(&path, out);
        }
    }
}
