//! Matrix stacks and GL's matrix constructors.

use crate::error::{GlError, GlResult};
use glam::{Mat4, Vec3, Vec4};

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

/// `glRotate`: `angle` degrees about `(x, y, z)`; a zero axis gives the identity.
pub fn rotation(angle_deg: f32, x: f32, y: f32, z: f32) -> Mat4 {
    let axis = Vec3::new(x, y, z);
    let len = axis.length();
    if len == 0.0 || !len.is_finite() {
        return Mat4::IDENTITY;
    }
    let (s, c) = angle_deg.to_radians().sin_cos();
    let Vec3 { x, y, z } = axis / len;
    let t = 1.0 - c;
    Mat4::from_cols(
        Vec4::new(x * x * t + c, y * x * t + z * s, x * z * t - y * s, 0.0),
        Vec4::new(x * y * t - z * s, y * y * t + c, y * z * t + x * s, 0.0),
        Vec4::new(x * z * t + y * s, y * z * t - x * s, z * z * t + c, 0.0),
        Vec4::W,
    )
}

/// `glFrustum`; `InvalidValue` when `near` or `far` is not positive or a pair is equal.
pub fn frustum(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<Mat4> {
    if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    let m = [
        [2.0 * n / (r - l), 0.0, 0.0, 0.0],
        [0.0, 2.0 * n / (t - b), 0.0, 0.0],
        [(r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1.0],
        [0.0, 0.0, -2.0 * f * n / (f - n), 0.0],
    ];
    Ok(from_cols_f64(m))
}

/// `glOrtho`; `InvalidValue` when a pair is equal.
pub fn ortho(l: f64, r: f64, b: f64, t: f64, n: f64, f: f64) -> GlResult<Mat4> {
    if l == r || b == t || n == f {
        return Err(GlError::InvalidValue);
    }
    let m = [
        [2.0 / (r - l), 0.0, 0.0, 0.0],
        [0.0, 2.0 / (t - b), 0.0, 0.0],
        [0.0, 0.0, -2.0 / (f - n), 0.0],
        [-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1.0],
    ];
    Ok(from_cols_f64(m))
}

fn from_cols_f64(m: [[f64; 4]; 4]) -> Mat4 {
    Mat4::from_cols_array_2d(&m.map(|col| col.map(|v| v as f32)))
}
