//! Cube-map face selection and the face coordinates and derivatives, as
//! `lp_build_cube_lookup` (`lp_bld_sample.c`) computes them per pixel.

/// A coordinate's sign bit, to flip another by (`LLVMBuildXor` on the bits).
fn sign(v: f32) -> u32 {
    v.to_bits() & 0x8000_0000
}

fn flip(v: f32, sign: u32) -> f32 {
    f32::from_bits(v.to_bits() ^ sign)
}

/// The major axis of (s, t, r): 0 for x, 1 for y, 2 for z. x wins over y
/// only when strictly larger; z wins ties (`as_ge_at`, `ar_ge_as_at`).
pub fn major_axis(c: [f32; 3]) -> usize {
    let (a_s, a_t, a_r) = (c[0].abs(), c[1].abs(), c[2].abs());
    let s_gt_t = a_s > a_t;
    let max_st = if a_s > a_t { a_s } else { a_t };
    if a_r >= max_st {
        2
    } else if s_gt_t {
        0
    } else {
        1
    }
}

/// The face (0..6: +X −X +Y −Y +Z −Z) of direction `c` on `axis`, and the
/// unprojected face coordinates (sc, tc) with their mirroring.
pub fn face_coords(c: [f32; 3], axis: usize) -> (u32, f32, f32, f32) {
    let ma = c[axis];
    let sm = sign(ma);
    let neg = |v: f32| flip(v, 0x8000_0000);
    let (sc, tc) = match axis {
        0 => (flip(neg(c[2]), sm), neg(c[1])),
        1 => (c[0], flip(c[2], sm)),
        _ => (flip(c[0], sm), neg(c[1])),
    };
    (axis as u32 * 2 + (sm >> 31), sc, tc, ma)
}

/// Face and (s, t) on it without derivatives: `sc·(0.5/|ma|) + 0.5`
/// (0 instead of the division when `ma` is 0).
pub fn lookup(c: [f32; 3]) -> (u32, [f32; 2]) {
    let axis = major_axis(c);
    let (face, sc, tc, ma) = face_coords(c, axis);
    let a = ma.abs();
    let ima = if a > 0.0 { 0.5 / a } else { 0.0 };
    (face, [sc * ima + 0.5, tc * ima + 0.5])
}

/// Face, (s, t) on it and the face coordinates' derivatives along x and y,
/// from the direction `c` and its derivatives `ddx`, `ddy` (the
/// `need_derivs` path: `1/ma` once, `|0.5·(1/ma)|` for the coordinates).
pub fn lookup_derivs(c: [f32; 3], ddx: [f32; 3], ddy: [f32; 3]) -> (u32, [f32; 2], [f32; 2], [f32; 2]) {
    let axis = major_axis(c);
    let (face, sc, tc, ma) = face_coords(c, axis);
    let ima = 1.0 / ma;
    let imahalf = 0.5 * ima;
    let imahalfpos = imahalf.abs();
    let (_, sdx, tdx, madx) = face_coords_of(ddx, axis, sign(ma));
    let (_, sdy, tdy, mady) = face_coords_of(ddy, axis, sign(ma));
    let madxdivma = madx * ima;
    let madydivma = mady * ima;
    let dsdx = (sdx - madxdivma * sc) * imahalf;
    let dtdx = (tdx - madxdivma * tc) * imahalf;
    let dsdy = (sdy - madydivma * sc) * imahalf;
    let dtdy = (tdy - madydivma * tc) * imahalf;
    (
        face,
        [sc * imahalfpos + 0.5, tc * imahalfpos + 0.5],
        [dsdx, dtdx],
        [dsdy, dtdy],
    )
}

/// A derivative vector mirrored as the coordinates of a face whose major
/// coordinate has sign `sm` (the sign is the coordinate's, not the derivative's).
fn face_coords_of(d: [f32; 3], axis: usize, sm: u32) -> (u32, f32, f32, f32) {
    let neg = |v: f32| flip(v, 0x8000_0000);
    let (s, t) = match axis {
        0 => (flip(neg(d[2]), sm), neg(d[1])),
        1 => (d[0], flip(d[2], sm)),
        _ => (flip(d[0], sm), neg(d[1])),
    };
    (0, s, t, d[axis])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_follow_the_gl_table() {
        // GL 1.5 table 3.19: +X sc=−rz tc=−ry; −X sc=+rz tc=−ry; +Y sc=+rx tc=+rz;
        // −Y sc=+rx tc=−rz; +Z sc=+rx tc=−ry; −Z sc=−rx tc=−ry; s = (sc/|ma| + 1)/2.
        let cases = [
            ([1.0, 0.5, -0.25], 0, [(0.25 + 1.0) / 2.0, (-0.5 + 1.0) / 2.0]),
            ([-1.0, 0.5, -0.25], 1, [(-0.25 + 1.0) / 2.0, (-0.5 + 1.0) / 2.0]),
            ([0.5, 2.0, 1.0], 2, [(0.25 + 1.0) / 2.0, (0.5 + 1.0) / 2.0]),
            ([0.5, -2.0, 1.0], 3, [(0.25 + 1.0) / 2.0, (-0.5 + 1.0) / 2.0]),
            ([0.5, 0.25, 1.0], 4, [(0.5 + 1.0) / 2.0, (-0.25 + 1.0) / 2.0]),
            ([0.5, 0.25, -1.0], 5, [(-0.5 + 1.0) / 2.0, (-0.25 + 1.0) / 2.0]),
        ];
        for (c, face, st) in cases {
            assert_eq!(lookup(c), (face, st), "{c:?}");
        }
    }

    #[test]
    fn ties_prefer_z_then_y() {
        assert_eq!(lookup([1.0, 1.0, 1.0]).0, 4);
        assert_eq!(lookup([1.0, -1.0, 0.5]).0, 3);
        assert_eq!(lookup([0.0, 0.0, 0.0]), (4, [0.5, 0.5]));
    }

    #[test]
    fn derivatives_of_the_face_coordinates() {
        // On +Z at (0.5, 0.25, 1) with d/dx = (0.1, 0, 0): s = (x/z + 1)/2
        // so ds/dx = 0.05, t unchanged; d/dy = (0, 0, 0.1): ds/dy = −x/z²·0.05 = −0.025,
        // dt/dy = +y/z²·0.05 = 0.0125.
        let (face, st, dx, dy) = lookup_derivs([0.5, 0.25, 1.0], [0.1, 0.0, 0.0], [0.0, 0.0, 0.1]);
        assert_eq!(face, 4);
        assert_eq!(st, [0.75, 0.375]);
        assert!((dx[0] - 0.05).abs() < 1e-7 && dx[1] == 0.0, "{dx:?}");
        assert!((dy[0] + 0.025).abs() < 1e-7 && (dy[1] - 0.0125).abs() < 1e-7, "{dy:?}");
    }
}
