//! Mesa's matrix analysis and inverse (`src/mesa/math/m_matrix.c`,
//! `src/util/u_math.c`), in f32 as Mesa computes them: which lighting space
//! Mesa picks depends on the analysis, and the normal matrix, object-space
//! light positions and clip planes come from its inverse. The analysis is
//! Mesa's `analyse_from_scratch` (Mesa analyses from the flags of the
//! calls that built a matrix when only `glRotate`/`glScale`/`glTranslate`
//! built it, which can classify the same values differently).

use glam::Mat4;

const ROTATION: u32 = 1;
const TRANSLATION: u32 = 2;
const UNIFORM_SCALE: u32 = 4;
const GENERAL_SCALE: u32 = 8;
const GENERAL_3D: u32 = 16;
const GENERAL: u32 = 32;

/// Mesa's matrix types, by the inverse each one takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    General,
    Identity,
    NoRot3d,
    Perspective,
    TwoD,
    NoRot2d,
    ThreeD,
}

/// `analyse_from_scratch`: the type and the geometry flags of `m`.
fn analyse(m: &[f32; 16]) -> (Kind, u32) {
    let mut mask = 0u32;
    for (i, &v) in m.iter().enumerate() {
        if v == 0.0 {
            mask |= 1 << i;
        }
    }
    for i in [0, 5, 10, 15] {
        if m[i] == 1.0 {
            mask |= 1 << (i + 16);
        }
    }
    let zero = |l: &[usize]| l.iter().fold(0u32, |a, &i| a | (1 << i));
    let one = |l: &[usize]| l.iter().fold(0u32, |a, &i| a | (1 << (i + 16)));
    let identity = one(&[0, 5, 10, 15]) | zero(&[1, 2, 3, 4, 6, 7, 8, 9, 11, 12, 13, 14]);
    let two_d_no_rot = zero(&[4, 8, 1, 9, 2, 6, 14, 3, 7, 11]) | one(&[10, 15]);
    let two_d = zero(&[8, 9, 2, 6, 14, 3, 7, 11]) | one(&[10, 15]);
    let three_d_no_rot = zero(&[4, 8, 1, 9, 2, 6, 3, 7, 11]) | one(&[15]);
    let three_d = zero(&[3, 7, 11]) | one(&[15]);
    let perspective = zero(&[4, 12, 1, 13, 2, 6, 3, 7, 15]);
    let no_trx = zero(&[12, 13, 14]);
    let sq = |x: f32| x * x;
    let eps = sq(1e-6);
    let mut flags = if mask & no_trx != no_trx { TRANSLATION } else { 0 };
    let dot3 = |a: usize, b: usize| m[a] * m[b] + m[a + 1] * m[b + 1] + m[a + 2] * m[b + 2];
    let kind = if mask == identity {
        Kind::Identity
    } else if mask & two_d_no_rot == two_d_no_rot {
        if mask & one(&[0, 5]) != one(&[0, 5]) {
            flags |= GENERAL_SCALE;
        }
        Kind::NoRot2d
    } else if mask & two_d == two_d {
        let mm = m[0] * m[0] + m[1] * m[1];
        let m4m4 = m[4] * m[4] + m[5] * m[5];
        let mm4 = m[0] * m[4] + m[1] * m[5];
        if sq(mm - 1.0) > eps || sq(m4m4 - 1.0) > eps {
            flags |= GENERAL_SCALE;
        }
        flags |= if sq(mm4) > eps { GENERAL_3D } else { ROTATION };
        Kind::TwoD
    } else if mask & three_d_no_rot == three_d_no_rot {
        if sq(m[0] - m[5]) < eps && sq(m[0] - m[10]) < eps {
            if sq(m[0] - 1.0) > eps {
                flags |= UNIFORM_SCALE;
            }
        } else {
            flags |= GENERAL_SCALE;
        }
        Kind::NoRot3d
    } else if mask & three_d == three_d {
        let (c1, c2, c3, d1) = (dot3(0, 0), dot3(4, 4), dot3(8, 8), dot3(0, 4));
        if sq(c1 - c2) < eps && sq(c1 - c3) < eps {
            if sq(c1 - 1.0) > eps {
                flags |= UNIFORM_SCALE;
            }
        } else {
            flags |= GENERAL_SCALE;
        }
        if sq(d1) < eps {
            let cp = [
                m[1] * m[6] - m[2] * m[5] - m[8],
                m[2] * m[4] - m[0] * m[6] - m[9],
                m[0] * m[5] - m[1] * m[4] - m[10],
            ];
            let len = cp[0] * cp[0] + cp[1] * cp[1] + cp[2] * cp[2];
            flags |= if len < eps { ROTATION } else { GENERAL_3D };
        } else {
            flags |= GENERAL_3D;
        }
        Kind::ThreeD
    } else if mask & perspective == perspective && m[11] == -1.0 {
        flags |= GENERAL;
        Kind::Perspective
    } else {
        flags |= GENERAL;
        Kind::General
    };
    (kind, flags)
}

/// `_math_matrix_is_length_preserving` after an analysis from scratch.
pub fn length_preserving(m: &Mat4) -> bool {
    let (_, flags) = analyse(&m.to_cols_array());
    flags & !(ROTATION | TRANSLATION) == 0
}

/// Mesa's inverse of `m` (`matrix_invert`): by type, in f32; the identity
/// for a singular matrix.
pub fn inverse(m: &Mat4) -> Mat4 {
    let a = m.to_cols_array();
    let (kind, flags) = analyse(&a);
    let out = match kind {
        Kind::General | Kind::Perspective => invert_general(&a),
        Kind::Identity => Some(IDENTITY),
        Kind::NoRot3d => invert_diagonal(&a, 3, flags),
        Kind::NoRot2d => invert_diagonal(&a, 2, flags),
        Kind::TwoD | Kind::ThreeD => invert_3d(&a, flags),
    };
    Mat4::from_cols_array(&out.unwrap_or(IDENTITY))
}

const IDENTITY: [f32; 16] = [
    1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
];

/// Element (row `r`, column `c`) of a column-major matrix.
const fn at(r: usize, c: usize) -> usize {
    c * 4 + r
}

/// `invert_matrix_3d_no_rot` / `invert_matrix_2d_no_rot` (`n` diagonal terms).
fn invert_diagonal(m: &[f32; 16], n: usize, flags: u32) -> Option<[f32; 16]> {
    if (0..n).any(|i| m[at(i, i)] == 0.0) {
        return None;
    }
    let mut out = IDENTITY;
    for i in 0..n {
        out[at(i, i)] = 1.0 / m[at(i, i)];
    }
    if flags & TRANSLATION != 0 {
        for i in 0..n {
            out[at(i, 3)] = -(m[at(i, 3)] * out[at(i, i)]);
        }
    }
    Some(out)
}

/// The translation column of an affine inverse whose 3x3 part is in `out`.
fn translation_part(m: &[f32; 16], out: &mut [f32; 16]) {
    for r in 0..3 {
        out[at(r, 3)] = -(m[at(0, 3)] * out[at(r, 0)] + m[at(1, 3)] * out[at(r, 1)] + m[at(2, 3)] * out[at(r, 2)]);
    }
}

/// `invert_matrix_3d`: transposes for rotations (scaled for a uniform
/// scale), else `invert_matrix_3d_general`.
fn invert_3d(m: &[f32; 16], flags: u32) -> Option<[f32; 16]> {
    if flags & !(ROTATION | TRANSLATION | UNIFORM_SCALE) != 0 {
        return invert_3d_general(m);
    }
    let mut out = IDENTITY;
    if flags & (UNIFORM_SCALE | ROTATION) == 0 {
        for r in 0..3 {
            out[at(r, 3)] = -m[at(r, 3)];
        }
        return Some(out);
    }
    let scale = if flags & UNIFORM_SCALE != 0 {
        let s = m[at(0, 0)] * m[at(0, 0)] + m[at(0, 1)] * m[at(0, 1)] + m[at(0, 2)] * m[at(0, 2)];
        if s == 0.0 {
            return None;
        }
        Some(1.0 / s)
    } else {
        None
    };
    for r in 0..3 {
        for c in 0..3 {
            out[at(c, r)] = scale.map_or(m[at(r, c)], |s| s * m[at(r, c)]);
        }
    }
    if flags & TRANSLATION != 0 {
        translation_part(m, &mut out);
    } else {
        for r in 0..3 {
            out[at(r, 3)] = 0.0;
        }
    }
    Some(out)
}

/// `invert_matrix_3d_general`: cofactors over the determinant, summed as
/// positive and negative terms.
fn invert_3d_general(m: &[f32; 16]) -> Option<[f32; 16]> {
    let e = |r: usize, c: usize| m[at(r, c)];
    let terms = [
        e(0, 0) * e(1, 1) * e(2, 2),
        e(1, 0) * e(2, 1) * e(0, 2),
        e(2, 0) * e(0, 1) * e(1, 2),
        -e(2, 0) * e(1, 1) * e(0, 2),
        -e(1, 0) * e(0, 1) * e(2, 2),
        -e(0, 0) * e(2, 1) * e(1, 2),
    ];
    let (mut pos, mut neg) = (0.0f32, 0.0f32);
    for t in terms {
        if t >= 0.0 {
            pos += t;
        } else {
            neg += t;
        }
    }
    let det = pos + neg;
    if det.abs() < 1e-25 {
        return None;
    }
    let det = 1.0 / det;
    let mut out = IDENTITY;
    out[at(0, 0)] = (e(1, 1) * e(2, 2) - e(2, 1) * e(1, 2)) * det;
    out[at(0, 1)] = -(e(0, 1) * e(2, 2) - e(2, 1) * e(0, 2)) * det;
    out[at(0, 2)] = (e(0, 1) * e(1, 2) - e(1, 1) * e(0, 2)) * det;
    out[at(1, 0)] = -(e(1, 0) * e(2, 2) - e(2, 0) * e(1, 2)) * det;
    out[at(1, 1)] = (e(0, 0) * e(2, 2) - e(2, 0) * e(0, 2)) * det;
    out[at(1, 2)] = -(e(0, 0) * e(1, 2) - e(1, 0) * e(0, 2)) * det;
    out[at(2, 0)] = (e(1, 0) * e(2, 1) - e(2, 0) * e(1, 1)) * det;
    out[at(2, 1)] = -(e(0, 0) * e(2, 1) - e(2, 0) * e(0, 1)) * det;
    out[at(2, 2)] = (e(0, 0) * e(1, 1) - e(1, 0) * e(0, 1)) * det;
    translation_part(m, &mut out);
    Some(out)
}

/// `util_invert_mat4x4`: Gauss-Jordan with partial pivoting, in f32.
// Each step reads one row of `w` and writes another, by index as the C does.
#[allow(clippy::needless_range_loop)]
fn invert_general(m: &[f32; 16]) -> Option<[f32; 16]> {
    // Rows of [m | I].
    let mut w = [[0.0f32; 8]; 4];
    for (r, row) in w.iter_mut().enumerate() {
        for c in 0..4 {
            row[c] = m[at(r, c)];
        }
        row[4 + r] = 1.0;
    }
    let mut idx = [0usize, 1, 2, 3];
    for col in 0..3 {
        // Pivot: compare from the bottom up, swapping larger ones upwards.
        for k in (col + 1..4).rev() {
            if w[idx[k]][col].abs() > w[idx[k - 1]][col].abs() {
                idx.swap(k, k - 1);
            }
        }
        if w[idx[col]][col] == 0.0 {
            return None;
        }
        let p = w[idx[col]];
        for &k in &idx[col + 1..] {
            let f = w[k][col] / p[col];
            for j in col + 1..8 {
                // Mesa skips the right-hand columns whose pivot-row entry is
                // 0 in the first two eliminations (no change but for -0/NaN).
                if col < 2 && j >= 4 && p[j] == 0.0 {
                    continue;
                }
                w[k][j] -= f * p[j];
            }
        }
    }
    let [r0, r1, r2, r3] = idx;
    if w[r3][3] == 0.0 {
        return None;
    }
    let s = 1.0 / w[r3][3];
    for j in 4..8 {
        w[r3][j] *= s;
    }
    let m2 = w[r2][3];
    let s = 1.0 / w[r2][2];
    for j in 4..8 {
        w[r2][j] = s * (w[r2][j] - w[r3][j] * m2);
    }
    let m1 = w[r1][3];
    let m0 = w[r0][3];
    for j in 4..8 {
        w[r1][j] -= w[r3][j] * m1;
        w[r0][j] -= w[r3][j] * m0;
    }
    let m1 = w[r1][2];
    let s = 1.0 / w[r1][1];
    for j in 4..8 {
        w[r1][j] = s * (w[r1][j] - w[r2][j] * m1);
    }
    let m0 = w[r0][2];
    for j in 4..8 {
        w[r0][j] -= w[r2][j] * m0;
    }
    let m0 = w[r0][1];
    let s = 1.0 / w[r0][0];
    for j in 4..8 {
        w[r0][j] = s * (w[r0][j] - w[r1][j] * m0);
    }
    let mut out = [0.0f32; 16];
    for (r, &row) in idx.iter().enumerate() {
        for c in 0..4 {
            out[at(r, c)] = w[row][4 + c];
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn close(a: &Mat4, b: &Mat4, tol: f32) -> bool {
        a.to_cols_array()
            .iter()
            .zip(b.to_cols_array())
            .all(|(x, y)| (x - y).abs() <= tol)
    }

    #[test]
    fn every_kind_inverts_its_matrix() {
        let cases = [
            Mat4::IDENTITY,
            Mat4::from_translation(Vec3::new(1.0, -2.0, 3.0)),
            Mat4::from_scale(Vec3::new(2.0, 0.5, 4.0)),
            Mat4::from_scale(Vec3::new(2.0, 0.5, 1.0)),
            Mat4::from_rotation_z(0.5),
            Mat4::from_rotation_y(0.5) * Mat4::from_translation(Vec3::new(0.0, 1.0, -5.0)),
            Mat4::from_rotation_x(0.3) * Mat4::from_scale(Vec3::splat(3.0)),
            Mat4::from_rotation_x(0.3) * Mat4::from_scale(Vec3::new(1.0, 2.0, 3.0)),
            Mat4::perspective_rh_gl(0.7, 1.0, 1.0, 20.0),
            Mat4::perspective_rh_gl(0.7, 1.0, 1.0, 20.0) * Mat4::from_rotation_y(0.2),
        ];
        for m in cases {
            // Against an independent f64 inverse: the f32 paths agree to a few ulps.
            let want = m.as_dmat4().inverse().as_mat4();
            assert!(close(&inverse(&m), &want, 1e-5), "{m:?}: {:?} vs {want:?}", inverse(&m));
        }
        // Rotations invert by transposing: exact.
        let r = Mat4::from_rotation_z(0.5);
        assert_eq!(inverse(&r), r.transpose());
        // Singular: the identity, as Mesa.
        assert_eq!(inverse(&Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0))), Mat4::IDENTITY);
    }

    #[test]
    fn length_preserving_follows_mesa_analysis() {
        assert!(length_preserving(&Mat4::IDENTITY));
        assert!(length_preserving(&Mat4::from_rotation_z(0.7)));
        assert!(length_preserving(&Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))));
        assert!(length_preserving(
            &(Mat4::from_rotation_x(0.3) * Mat4::from_rotation_y(1.1))
        ));
        assert!(!length_preserving(&Mat4::from_scale(Vec3::splat(2.0))));
        assert!(!length_preserving(&Mat4::perspective_rh_gl(1.0, 1.0, 0.1, 10.0)));
    }
}
