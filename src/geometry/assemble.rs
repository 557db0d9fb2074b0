//! Primitive assembly: the ten GL modes as points, lines and triangles, with
//! the provoking vertex and, for triangles, which edges are polygon boundary
//! edges (for polygon mode `Line`/`Point`). Quads and polygons split the way
//! llvmpipe splits them (`docs/llvmpipe-facts.md` §3 and §12).

use crate::state::PrimitiveMode;

/// One assembled primitive, as indices into the draw's vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Point(usize),
    /// Segment `a → b`; flat shading takes the color of `provoking`.
    Line {
        a: usize,
        b: usize,
        provoking: usize,
    },
    /// Triangle `v`; `edges[k]` says whether edge `v[k] → v[k+1]` is a boundary edge.
    Triangle {
        v: [usize; 3],
        provoking: usize,
        edges: [bool; 3],
    },
}

/// How llvmpipe splits `GL_QUADS`: it depends on how the draw is made and on
/// the path it takes through Mesa's draw module (`docs/llvmpipe-facts.md` §12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuadSplit {
    /// `(v0, v1, v2), (v0, v2, v3)`: non-indexed draws with every vertex
    /// inside the view volume, both polygon modes `Fill`, and smooth shading
    /// or a colour that is not per vertex.
    Direct,
    /// `(v0, v1, v3), (v1, v2, v3)`: every other draw (indexed, flat-shaded
    /// per-vertex colour, needing clipping, or a face drawn as lines or points).
    Pipeline,
}

/// Calls `f` with each primitive `mode` makes of `n` vertices, in order.
/// Incomplete trailing primitives are ignored, as GL requires.
pub fn assemble(mode: PrimitiveMode, n: usize, quads: QuadSplit, mut f: impl FnMut(Primitive)) {
    let tri = |v: [usize; 3], provoking: usize, edges: [bool; 3]| Primitive::Triangle { v, provoking, edges };
    match mode {
        PrimitiveMode::Points => (0..n).for_each(|i| f(Primitive::Point(i))),
        PrimitiveMode::Lines => {
            for i in (0..n.saturating_sub(1)).step_by(2) {
                f(Primitive::Line {
                    a: i,
                    b: i + 1,
                    provoking: i + 1,
                });
            }
        }
        PrimitiveMode::LineStrip | PrimitiveMode::LineLoop => {
            for i in 1..n {
                f(Primitive::Line {
                    a: i - 1,
                    b: i,
                    provoking: i,
                });
            }
            if mode == PrimitiveMode::LineLoop && n >= 2 {
                f(Primitive::Line {
                    a: n - 1,
                    b: 0,
                    provoking: 0,
                });
            }
        }
        PrimitiveMode::Triangles => {
            for i in (0..n.saturating_sub(2)).step_by(3) {
                f(tri([i, i + 1, i + 2], i + 2, [true; 3]));
            }
        }
        PrimitiveMode::TriangleStrip => {
            for i in 0..n.saturating_sub(2) {
                let v = if i % 2 == 0 {
                    [i, i + 1, i + 2]
                } else {
                    [i + 1, i, i + 2]
                };
                f(tri(v, i + 2, [true; 3]));
            }
        }
        PrimitiveMode::TriangleFan => {
            for i in 1..n.saturating_sub(1) {
                f(tri([0, i, i + 1], i + 1, [true; 3]));
            }
        }
        PrimitiveMode::Quads => {
            for q in (0..n.saturating_sub(3)).step_by(4) {
                let [v0, v1, v2, v3] = [q, q + 1, q + 2, q + 3];
                match quads {
                    QuadSplit::Direct => {
                        f(tri([v0, v1, v2], v3, [true, true, false]));
                        f(tri([v0, v2, v3], v3, [false, true, true]));
                    }
                    QuadSplit::Pipeline => {
                        f(tri([v0, v1, v3], v3, [true, false, true]));
                        f(tri([v1, v2, v3], v3, [true, true, false]));
                    }
                }
            }
        }
        PrimitiveMode::QuadStrip => {
            for q in (0..n.saturating_sub(3)).step_by(2) {
                let [v0, v1, v2, v3] = [q, q + 1, q + 2, q + 3];
                // Boundary in polygon order v0 v1 v3 v2.
                f(tri([v0, v1, v3], v3, [true, true, false]));
                f(tri([v0, v3, v2], v3, [false, true, true]));
            }
        }
        PrimitiveMode::Polygon => {
            if n >= 3 {
                for i in 1..n - 1 {
                    f(tri([0, i, i + 1], 0, [i == 1, true, i + 1 == n - 1]));
                }
            }
        }
    }
}
