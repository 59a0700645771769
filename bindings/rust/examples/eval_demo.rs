//! Evaluate a biquadratic patch: a point with its partial derivatives and unit normal, then a
//! small grid; finally the normal at the pole of the teapot's lid, where S_u x S_v vanishes.
//!
//! Run with `cargo run --example eval_demo` (see docs/rust.md for how the library is found).

use bezsurf::{NormalKind, Outputs, Patch, Surface};

fn main() -> Result<(), bezsurf::Error> {
    println!("libbezsurf {}", bezsurf::version_string());

    // The worked example of MATH.md: 3 x 3 control points, row i along u.
    let net = [
        1., 0., 2., 1., 2., 4., 1., 3., 2., //
        2., 1., 0., 2., 2., 2., 2., 4., 0., //
        4., 1., 0., 3., 3., 2., 4., 4., 2.,
    ];
    let patch = Patch::new(2, 2, 3, &net)?;

    let (mut pos, mut du, mut dv) = ([0.0; 3], [0.0; 3], [0.0; 3]);
    patch.eval_with(&[0.5], &[0.5], Outputs::new().pos(&mut pos).du(&mut du).dv(&mut dv))?;
    let (mut nrm, mut kind) = ([0.0; 3], [0u8; 1]);
    patch.eval_normal(&[0.5], &[0.5], Outputs::new().normal(&mut nrm).kind(&mut kind))?;
    println!("S(1/2,1/2)   = {pos:?}   (exactly (17/8, 9/4, 13/8))");
    println!("S_u(1/2,1/2) = {du:?}");
    println!("S_v(1/2,1/2) = {dv:?}");
    println!("N(1/2,1/2)   = {nrm:?} ({:?})", NormalKind::from_byte(kind[0]).unwrap());

    // A 3 x 3 grid: point (a, b) at index a * 3 + b.
    let t = [0.0, 0.5, 1.0];
    let mut grid = [0.0; 27];
    patch.eval_grid(&t, &t, Outputs::new().pos(&mut grid))?;
    for (a, u) in t.iter().enumerate() {
        for (b, v) in t.iter().enumerate() {
            let k = 3 * (a * 3 + b);
            println!("S({u:.1},{v:.1}) = ({:6.3}, {:6.3}, {:6.3})", grid[k], grid[k + 1], grid[k + 2]);
        }
    }

    // The teapot's lid is made of patches with a collapsed edge at the knob's top.
    let teapot = Surface::builtin("teapot")?;
    for (i, p) in teapot.iter().enumerate() {
        let c = p.ctrl();
        if c[..3] == c[3..6] && c[3..6] == c[6..9] && c[6..9] == c[9..12] {
            let (mut n, mut k) = ([0.0; 3], [0u8; 1]);
            p.eval_normal(&[0.0], &[0.5], Outputs::new().normal(&mut n).kind(&mut k))?;
            let kind = NormalKind::from_byte(k[0]).unwrap();
            println!("teapot patch {i:2}: pole at {:?}, normal {n:?} ({kind:?})", &c[..3]);
            break;
        }
    }
    Ok(())
}
