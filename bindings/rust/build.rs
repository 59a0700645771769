//! Finds libbezsurf for linking.
//!
//! Order: `BEZSURF_LIB_DIR` if set; else the `-L` directories reported by the `pkg-config`
//! program (`pkg-config --libs-only-L bezsurf`) when it is installed and knows bezsurf; else the
//! linker's default search path. The crate always links the shared library (`dylib=bezsurf`).

use std::env;
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=BEZSURF_LIB_DIR");
    println!("cargo:rerun-if-env-changed=PKG_CONFIG_PATH");
    println!("cargo:rerun-if-env-changed=PKG_CONFIG_LIBDIR");

    let dirs: Vec<String> = match env::var("BEZSURF_LIB_DIR") {
        Ok(dir) if !dir.is_empty() => vec![dir],
        _ => pkg_config_dirs(),
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
}

/// The `-L` directories pkg-config reports for bezsurf, or nothing if pkg-config is missing or
/// does not know the package.
fn pkg_config_dirs() -> Vec<String> {
    let out = match Command::new("pkg-config").args(["--libs-only-L", "bezsurf"]).output() {
        Ok(out) if out.status.success() => out,
        _ => return Vec::new(),
    };
    String::from_utf8_lossy(&out.stdout)
        .split_whitespace()
        .filter_map(|tok| tok.strip_prefix("-L"))
        .filter(|dir| !dir.is_empty())
        .map(str::to_owned)
        .collect()
}
