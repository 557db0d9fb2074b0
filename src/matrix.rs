//! Matrix stacks and GL's matrix constructors.

use crate::error::{GlError, GlResult};
use glam::Mat4;

/// Which stack matrix calls act on (`glMatrixMode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MatrixMode {
    Modelview,
    Projection,
    Texture,
}

/// Stack depths, as Mesa reports them (`GL_MAX_*_STACK_DEPTH`).
pub const MAX_MODELVIEW_DEPTH: usize = 32;
pub const MAX_PROJECTION_DEPTH: usize = 32;
pub const MAX_TEXTURE_DEPTH: usize = 10;

/// A matrix stack; the top is the current matrix. Never empty.
#[derive(Clone, Debug)]
pub struct MatrixStack {
    stack: Vec<Mat4>,
    max_depth: usize,
}

impl MatrixStack {
    pub fn new(max_depth: usize) -> MatrixStack {
        let mut stack = Vec::with_capacity(max_depth);
        stack.push(Mat4::IDENTITY);
        MatrixStack { stack, max_depth }
    }

    pub fn top(&self) -> &Mat4 {
        self.stack.last().expect("a matrix stack is never empty")
    }

    pub fn top_mut(&mut self) -> &mut Mat4 {
        self.stack.last_mut().expect("a matrix stack is never empty")
    }

    pub fn depth(&self) -> usize {
        self.stack.len()
    }

    pub fn max_depth(&self) -> usize {
        self.max_depth
    }

    pub fn push(&mut self) -> GlResult {
        if self.stack.len() >= self.max_depth {
            return Err(GlError::StackOverflow);
        }
        let top = *self.top();
        self.stack.push(top);
        Ok(())
    }

    pub fn pop(&mut self) -> GlResult {
        if self.stack.len() <= 1 {
            return Err(GlError::StackUnderflow);
        }
        self.stack.pop();
        Ok(())
    }

    /// `top = top * m`, the way every `glMult*`-style call composes.
    pub fn mult(&mut self, m: &Mat4) {
        let top = self.top_mut();
        *top *= *m;
    }
}

/// `glRotate`: `angle` degrees about `(x, y, z)`, built as Mesa's
/// `_math_matrix_rotate` (`math/m_matrix.c`) builds it, bit for bit: the
/// angle to radians in double, `sinf`/`cosf`; an axis along x, y or z gets
/// exact ones and zeros; any other axis is normalized in f32 and, when its
/// length is at most 1e-4, gives the identity (no rotation).
pub fn rotation(angle_deg: f32, x: f32, y: f32, z: f32) -> Mat4 {
    let rad = (f64::from(angle_deg) * std::f64::consts::PI / 180.0) as f32;
    let (s, c) = (rad.sin(), rad.cos());
    let mut m = Mat4::IDENTITY.to_cols_array();
    // M(row, col) = m[col * 4 + row].
    let mut set = |row: usize, col: usize, v: f32| m[col * 4 + row] = v;
    if x == 0.0 && y == 0.0 && z != 0.0 {
        let s = if z < 0.0 { -s } else { s };
        set(0, 0, c);
        set(1, 1, c);
        set(0, 1, -s);
        set(1, 0, s);
    } else if x == 0.0 && y != 0.0 && z == 0.0 {
        let s = if y < 0.0 { -s } else { s };
        set(0, 0, c);
        set(2, 2, c);
        set(0, 2, s);
        set(2, 0, -s);
    } else if x != 0.0 && y == 0.0 && z == 0.0 {
        let s = if x < 0.0 { -s } else { s };
        set(1, 1, c);
        set(2, 2, c);
        set(1, 2, -s);
        set(2, 1, s);
    } else {
        let mag = (x * x + y * y + z * z).sqrt();
        if mag <= 1.0e-4 {
            return Mat4::IDENTITY;
        }
        let (x, y, z) = (x / mag, y / mag, z / mag);
        let (xx, yy, zz, xy, yz, zx) = (x * x, y * y, z * z, x * y, y * z, z * x);
        let (xs, ys, zs) = (x * s, y * s, z * s);
        let one_c = 1.0 - c;
        set(0, 0, (one_c * xx) + c);
        set(0, 1, (one_c * xy) - zs);
        set(0, 2, (one_c * zx) + ys);
        set(1, 0, (one_c * xy) + zs);
        set(1, 1, (one_c * yy) + c);
        set(1, 2, (one_c * yz) - xs);
        set(2, 0, (one_c * zx) - ys);
        set(2, 1, (one_c * yz) + xs);
        set(2, 2, (one_c * zz) + c);
    }
    Mat4::from_cols_array(&m)
}

/// `glFrustum`; `InvalidValue` when `near` or `far` is not positive or a pair is equal.
pub fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<Mat4> {
    if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    // Mesa casts the arguments to f32 and builds the matrix in f32
    // (`matrix_frustum`, `main/matrix.c`; `_math_matrix_frustum`, `math/m_matrix.c`).
    let [l, r, b, t, n, f] = [l, r, b, t, n, f].map(|v| v as f32);
    let m = [
        [(2.0 * n) / (r - l), 0.0, 0.0, 0.0],
        [0.0, (2.0 * n) / (t - b), 0.0, 0.0],
        [(r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1.0],
        [0.0, 0.0, -(2.0 * f * n) / (f - n), 0.0],
    ];
    Ok(Mat4::from_cols_array_2d(&m))
}

/// `glOrtho`; `InvalidValue` when a pair is equal.
pub fn ortho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<Mat4> {
    if l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    // In f32 from f32 arguments, as Mesa (`_math_float_ortho`, `math/m_matrix.c`).
    let [l, r, b, t, n, f] = [l, r, b, t, n, f].map(|v| v as f32);
    let m = [
        [2.0 / (r - l), 0.0, 0.0, 0.0],
        [0.0, 2.0 / (t - b), 0.0, 0.0],
        [0.0, 0.0, -2.0 / (f - n), 0.0],
        [-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1.0],
    ];
    Ok(Mat4::from_cols_array_2d(&m))
}
