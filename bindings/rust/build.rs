//! Finds libbezsurf for linking.
//!
//! Order: `BEZSURF_LIB_DIR` if set; else the `-L` directories reported by the `pkg-config`
//! program (`pkg-config --libs-only-L bezsurf`) when it is installed and knows bezsurf; else the
//! linker's default search path. The crate always links the shared library (`dylib=bezsurf`).
//!
//! When none of these has the library, linking fails later with only the linker's "cannot find
//! -lbezsurf"; so the script looks for the file itself and, if it is nowhere, prints (as cargo
//! warnings, shown for path dependencies and for this package) how to point it at the library.
//! A `BEZSURF_LIB_DIR` without the library is a mistake the script reports as an error at once.

use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What pkg-config said about bezsurf.
enum PkgConfig {
    /// Known, with these `-L` directories (possibly none: the linker's default path).
    Found(Vec<String>),
    /// The program ran but does not know bezsurf.
    Unknown,
    /// The program is not installed or could not run.
    Missing,
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    for var in [
        "BEZSURF_LIB_DIR",
        "PKG_CONFIG",
        "PKG_CONFIG_PATH",
        "PKG_CONFIG_LIBDIR",
        "PKG_CONFIG_SYSROOT_DIR",
        "LIBRARY_PATH",
    ] {
        println!("cargo:rerun-if-env-changed={var}");
    }
    let file = library_file_name();

    let (dirs, pkg) = match env::var("BEZSURF_LIB_DIR") {
        Ok(dir) if !dir.is_empty() => {
            if !Path::new(&dir).join(&file).exists() {
                eprintln!(
                    "error: BEZSURF_LIB_DIR is set to `{dir}`, which has no `{file}`.\n\
                     Point it at the directory holding the library, e.g. the `lib` directory of a \
                     CMake build of libbezsurf (`cmake --build build`, then \
                     BEZSURF_LIB_DIR=$PWD/build/lib), or unset it to ask pkg-config."
                );
                std::process::exit(1);
            }
            (vec![dir], None)
        }
        _ => match pkg_config() {
            PkgConfig::Found(dirs) => (dirs, None),
            other => (Vec::new(), Some(other)),
        },
    };
    for dir in &dirs {
        println!("cargo:rustc-link-search=native={dir}");
        // Lets this package's own test and example programs find the library at run time
        // without LD_LIBRARY_PATH; crates that depend on this one are not affected (link
        // arguments do not propagate). Doc tests are linked by rustdoc without it.
        println!("cargo:rustc-link-arg=-Wl,-rpath,{dir}");
    }
    if let Some(dir) = dirs.first() {
        // Published to dependents as DEP_BEZSURF_LIB_DIR (thanks to `links = "bezsurf"`).
        println!("cargo:lib_dir={dir}");
    }
    println!("cargo:rustc-link-lib=dylib=bezsurf");

    // Nothing configured: the linker's default path must have the library. Say how to fix it
    // if it clearly does not.
    if let Some(pkg) = pkg {
        if linker_finds(&file) == Some(false) {
            explain_missing(&file, &pkg);
        }
    }
}

/// The file the linker looks for when asked for `-lbezsurf` on the target.
fn library_file_name() -> String {
    match env::var("CARGO_CFG_TARGET_OS").as_deref() {
        Ok("macos") | Ok("ios") => "libbezsurf.dylib".into(),
        Ok("windows") => "bezsurf.lib".into(),
        _ => "libbezsurf.so".into(),
    }
}

/// The `-L` directories pkg-config reports for bezsurf.
fn pkg_config() -> PkgConfig {
    let prog = env::var("PKG_CONFIG").unwrap_or_else(|_| "pkg-config".into());
    let out = match Command::new(prog).args(["--libs-only-L", "bezsurf"]).output() {
        Ok(out) => out,
        Err(_) => return PkgConfig::Missing,
    };
    if !out.status.success() {
        return PkgConfig::Unknown;
    }
    PkgConfig::Found(
        String::from_utf8_lossy(&out.stdout)
            .split_whitespace()
            .filter_map(|tok| tok.strip_prefix("-L"))
            .filter(|dir| !dir.is_empty())
            .map(str::to_owned)
            .collect(),
    )
}

/// Whether the C compiler driver (which rustc uses as the linker on Unix) finds `file` in its
/// library search path: `Some(false)` only when it clearly does not; `None` when that cannot be
/// told (cross-compiling, no compiler, extra `-L` flags in RUSTFLAGS).
fn linker_finds(file: &str) -> Option<bool> {
    if env::var("TARGET").ok()? != env::var("HOST").ok()? || file.ends_with(".lib") {
        return None;
    }
    let rustflags = env::var("CARGO_ENCODED_RUSTFLAGS").unwrap_or_default();
    if rustflags.split('\x1f').any(|f| f.starts_with("-L") || f.contains("link-arg")) {
        return None;
    }
    let cc = env::var("CC").unwrap_or_else(|_| "cc".into());
    let out = Command::new(cc).arg(format!("-print-file-name={file}")).output().ok()?;
    if !out.status.success() {
        return None;
    }
    // gcc and clang print the bare name back when they find nothing.
    let path = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    Some(path.is_absolute() && path.exists())
}

/// Cargo warnings (one per line) explaining how to point the build at the library.
fn explain_missing(file: &str, pkg: &PkgConfig) {
    let why = match pkg {
        PkgConfig::Missing => "the `pkg-config` program is not installed".to_owned(),
        PkgConfig::Unknown => {
            "pkg-config does not know `bezsurf` (no bezsurf.pc in its search path)".to_owned()
        }
        PkgConfig::Found(_) => return,
    };
    let lines = [
        format!("libbezsurf not found: BEZSURF_LIB_DIR is not set, {why}, and the linker's default path has no {file}; linking will fail with `cannot find -lbezsurf`."),
        "Point the build at the library in one of these ways:".to_owned(),
        "  - install it (`cmake --install build`, prefix /usr/local by default), so that pkg-config finds bezsurf.pc;".to_owned(),
        "  - or set PKG_CONFIG_PATH to the directory holding bezsurf.pc (<prefix>/lib/pkgconfig);".to_owned(),
        "  - or set BEZSURF_LIB_DIR to the directory holding the library (e.g. build/lib of a CMake build).".to_owned(),
        "Programs then find libbezsurf.so.1 at run time if it is in a system directory, else through LD_LIBRARY_PATH or an rpath.".to_owned(),
    ];
    for line in lines {
        println!("cargo:warning={line}");
    }
}
