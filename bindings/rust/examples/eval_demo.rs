//! Evaluate a bicubic patch whose u = 0 edge is collapsed to one point (like the top of the Utah
//! teapot's lid): positions, unit normals and their kinds at a few points, scattered and on a
//! grid. The Rust twin of examples/eval_demo.c, with the same output.
//!
//! Run with `cargo run --example eval_demo` (see docs/rust.md for how the library is found).

use std::process::ExitCode;

use bezsurf::{sys, Outputs, Patch, StridedMut};

fn kind_name(k: u8) -> &'static str {
    match k {
        sys::BS_NORMAL_REGULAR => "regular",
        sys::BS_NORMAL_LIMIT => "limit",
        _ => "undefined",
    }
}

fn run() -> Result<(), bezsurf::Error> {
    // Row i = 0 is the apex (0, 0, 1); the other rows spread out into a dome.
    let r = [0.0, 0.6, 1.0, 1.2];
    let z = [1.0, 1.0, 0.6, 0.0];
    let (x, y) = ([1.0, 1.0, 0.55, 0.0], [0.0, 0.55, 1.0, 1.0]); // quarter circle
    let mut ctrl = Vec::with_capacity(48);
    for i in 0..4 {
        for j in 0..4 {
            ctrl.extend([r[i] * x[j], r[i] * y[j], z[i]]);
        }
    }
    let p = Patch::new(3, 3, 3, &ctrl)?;

    const N: usize = 5;
    let u = [0.0, 0.0, 0.5, 1.0, 0.25];
    let v = [0.0, 0.5, 0.5, 1.0, 0.75];
    // Structure of arrays, as in the C example: one array per coordinate.
    let mut pos = [[0.0; N]; 3];
    let mut nrm = [[0.0; N]; 3];
    let mut kind = [0u8; N];
    {
        let [px, py, pz] = &mut pos;
        let [nx, ny, nz] = &mut nrm;
        let pos_views = [StridedMut::from(&mut px[..]), (&mut py[..]).into(), (&mut pz[..]).into()];
        let nrm_views = [StridedMut::from(&mut nx[..]), (&mut ny[..]).into(), (&mut nz[..]).into()];
        p.eval_normal(&u, &v, Outputs::new().pos(pos_views).normal(nrm_views).kind(&mut kind))?;
    }
    println!(
        "libbezsurf {}: bicubic patch with its u = 0 edge collapsed to a point",
        bezsurf::version_string()
    );
    println!("    u     v   |  position                 |  unit normal                 kind");
    for k in 0..N {
        println!(
            "{:5.2} {:5.2} | {:7.4} {:7.4} {:7.4} | {:8.5} {:8.5} {:8.5}  {}",
            u[k],
            v[k],
            pos[0][k],
            pos[1][k],
            pos[2][k],
            nrm[0][k],
            nrm[1][k],
            nrm[2][k],
            kind_name(kind[k])
        );
    }

    // A 3 x 3 grid: only the points on u = 0 take the limit rule.
    let g = [0.0, 0.5, 1.0];
    let mut gn = [0.0; 27];
    let mut gkind = [0u8; 9];
    p.eval_grid(&g, &g, Outputs::new().normal(&mut gn).kind(&mut gkind))?;
    println!("grid normal kinds (rows u = 0, 0.5, 1):");
    for a in 0..3 {
        println!(
            "  {:<9} {:<9} {:<9}",
            kind_name(gkind[a * 3]),
            kind_name(gkind[a * 3 + 1]),
            kind_name(gkind[a * 3 + 2])
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("eval_demo: {e}");
            ExitCode::FAILURE
        }
    }
}
