//! Evaluators (GL 1.5 §5.1): one- and two-dimensional Bézier maps of
//! vertices, normals, colours, colour indices and texture coordinates,
//! `glEvalCoord`, `glEvalPoint`, `glMapGrid` and `glEvalMesh`.
//!
//! Evaluated as Mesa 22.3.6 does (`src/mesa/math/m_eval.c`: Horner's
//! scheme for points, de Casteljau's for `GL_AUTO_NORMAL`'s derivatives;
//! `src/mesa/vbo/vbo_exec_eval.c`, `vbo_exec_api.c`, `main/draw.c`), in the
//! same `f32` operations in the same order, so that positions have the same
//! bits as llvmpipe's. As in Mesa, `GL_MAP*_INDEX` is stored and queryable
//! but not evaluated (an RGBA context has no use for it).

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::state::PrimitiveMode;

/// `GL_MAX_EVAL_ORDER`, Mesa's `MAX_EVAL_ORDER`.
pub const MAX_EVAL_ORDER: usize = 30;

/// What a map produces, in the order of the GL enumerants
/// (`GL_MAP1_COLOR_4` = 0x0D90 … `GL_MAP1_VERTEX_4` = 0x0D98, and `MAP2`'s
/// from 0x0DB0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapKind {
    Color4,
    Index,
    Normal,
    Texture1,
    Texture2,
    Texture3,
    Texture4,
    Vertex3,
    Vertex4,
}

impl MapKind {
    pub const ALL: [MapKind; 9] = [
        MapKind::Color4,
        MapKind::Index,
        MapKind::Normal,
        MapKind::Texture1,
        MapKind::Texture2,
        MapKind::Texture3,
        MapKind::Texture4,
        MapKind::Vertex3,
        MapKind::Vertex4,
    ];

    /// The number of values of each control point.
    pub fn components(self) -> usize {
        match self {
            MapKind::Index | MapKind::Texture1 => 1,
            MapKind::Texture2 => 2,
            MapKind::Normal | MapKind::Texture3 | MapKind::Vertex3 => 3,
            MapKind::Color4 | MapKind::Texture4 | MapKind::Vertex4 => 4,
        }
    }

    /// The one control point of the initial map (GL 1.5 table 5.2's
    /// defaults, Mesa's `init_maps`).
    fn initial(self) -> &'static [f32] {
        match self {
            MapKind::Color4 => &[1.0, 1.0, 1.0, 1.0],
            MapKind::Index => &[1.0],
            MapKind::Normal => &[0.0, 0.0, 1.0],
            MapKind::Texture1 => &[0.0],
            MapKind::Texture2 => &[0.0, 0.0],
            MapKind::Texture3 => &[0.0, 0.0, 0.0],
            MapKind::Texture4 => &[0.0, 0.0, 0.0, 1.0],
            MapKind::Vertex3 => &[0.0, 0.0, 0.0],
            MapKind::Vertex4 => &[0.0, 0.0, 0.0, 1.0],
        }
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// A map target: its dimension (1 or 2) and kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapTarget {
    pub two_d: bool,
    pub kind: MapKind,
}

impl MapTarget {
    /// `GL_MAP1_*` (0x0D90..=0x0D98) or `GL_MAP2_*` (0x0DB0..=0x0DB8).
    pub fn from_gl(v: u32) -> Option<MapTarget> {
        let (two_d, i) = match v {
            0x0D90..=0x0D98 => (false, v - 0x0D90),
            0x0DB0..=0x0DB8 => (true, v - 0x0DB0),
            _ => return None,
        };
        Some(MapTarget {
            two_d,
            kind: MapKind::ALL[i as usize],
        })
    }

    /// The bit of this map's enable in [`EvalEnables`].
    pub fn bit(self) -> u32 {
        1 << (self.kind.index() + if self.two_d { 9 } else { 0 })
    }
}

/// Which maps are enabled (`glEnable(GL_MAP1_*)`, …): bit `i` for the
/// `MAP1` kind `i`, `9 + i` for `MAP2`'s, and [`AUTO_NORMAL`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EvalEnables(pub u32);

/// The bit of `GL_AUTO_NORMAL` in [`EvalEnables`].
pub const AUTO_NORMAL: u32 = 1 << 18;

impl EvalEnables {
    fn map1(self, k: MapKind) -> bool {
        self.0 & MapTarget { two_d: false, kind: k }.bit() != 0
    }
    fn map2(self, k: MapKind) -> bool {
        self.0 & MapTarget { two_d: true, kind: k }.bit() != 0
    }
}

/// A one-dimensional map: `order` control points of `components` values.
#[derive(Clone, Debug, PartialEq)]
pub struct Map1 {
    pub order: usize,
    pub u1: f32,
    pub u2: f32,
    du: f32,
    pub points: Vec<f32>,
}

/// A two-dimensional map: `uorder × vorder` control points, `v` varying
/// fastest (Mesa's layout).
#[derive(Clone, Debug, PartialEq)]
pub struct Map2 {
    pub uorder: usize,
    pub vorder: usize,
    pub u1: f32,
    pub u2: f32,
    pub v1: f32,
    pub v2: f32,
    du: f32,
    dv: f32,
    pub points: Vec<f32>,
}

/// `glMapGrid1`/`glMapGrid2`'s state (`GL_MAP1_GRID_*`, `GL_MAP2_GRID_*`),
/// part of `GL_EVAL_BIT`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub un1: i32,
    pub u1_1: f32,
    pub u1_2: f32,
    du1: f32,
    pub un2: i32,
    pub u2_1: f32,
    pub u2_2: f32,
    du2: f32,
    pub vn2: i32,
    pub v2_1: f32,
    pub v2_2: f32,
    dv2: f32,
}

impl Default for Grid {
    fn default() -> Grid {
        Grid {
            un1: 1,
            u1_1: 0.0,
            u1_2: 1.0,
            du1: 1.0,
            un2: 1,
            u2_1: 0.0,
            u2_2: 1.0,
            du2: 1.0,
            vn2: 1,
            v2_1: 0.0,
            v2_2: 1.0,
            dv2: 1.0,
        }
    }
}

/// `glGetMap`'s query.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapQuery {
    /// `GL_COEFF`
    Coeff,
    /// `GL_ORDER`
    Order,
    /// `GL_DOMAIN`
    Domain,
}

impl MapQuery {
    pub fn from_gl(v: u32) -> Option<MapQuery> {
        match v {
            0x0A00 => Some(MapQuery::Coeff),
            0x0A01 => Some(MapQuery::Order),
            0x0A02 => Some(MapQuery::Domain),
            _ => None,
        }
    }
}

/// `glEvalMesh`'s mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshMode {
    Point,
    Line,
    Fill,
}

impl MeshMode {
    /// `GL_POINT`, `GL_LINE`, `GL_FILL`.
    pub fn from_gl(v: u32) -> Option<MeshMode> {
        match v {
            0x1B00 => Some(MeshMode::Point),
            0x1B01 => Some(MeshMode::Line),
            0x1B02 => Some(MeshMode::Fill),
            _ => None,
        }
    }
}

/// The maps and the grids.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluators {
    pub map1: [Map1; 9],
    pub map2: [Map2; 9],
    pub grid: Grid,
}

impl Default for Evaluators {
    fn default() -> Evaluators {
        Evaluators {
            map1: MapKind::ALL.map(|k| Map1 {
                order: 1,
                u1: 0.0,
                u2: 1.0,
                du: 1.0,
                points: k.initial().to_vec(),
            }),
            map2: MapKind::ALL.map(|k| Map2 {
                uorder: 1,
                vorder: 1,
                u1: 0.0,
                u2: 1.0,
                v1: 0.0,
                v2: 1.0,
                du: 1.0,
                dv: 1.0,
                points: k.initial().to_vec(),
            }),
            grid: Grid::default(),
        }
    }
}

/// `glMap1`'s checks, in Mesa's order (`map1`, `src/mesa/main/eval.c`):
/// the target and the number of values `points` must hold.
pub fn check_map1(target: u32, u1: f32, u2: f32, stride: i32, order: i32) -> GlResult<(MapTarget, usize)> {
    if u1 == u2 || !(1..=MAX_EVAL_ORDER as i32).contains(&order) {
        return Err(GlError::InvalidValue);
    }
    let t = MapTarget::from_gl(target)
        .filter(|t| !t.two_d)
        .ok_or(GlError::InvalidEnum)?;
    let k = t.kind.components();
    if stride < k as i32 {
        return Err(GlError::InvalidValue);
    }
    Ok((t, (order as usize - 1) * stride as usize + k))
}

/// `glMap2`'s checks, in Mesa's order (`map2`): the target and the number
/// of values `points` must hold.
#[allow(clippy::too_many_arguments)]
pub fn check_map2(
    target: u32,
    u1: f32,
    u2: f32,
    ustride: i32,
    uorder: i32,
    v1: f32,
    v2: f32,
    vstride: i32,
    vorder: i32,
) -> GlResult<(MapTarget, usize)> {
    let orders = 1..=MAX_EVAL_ORDER as i32;
    if u1 == u2 || v1 == v2 || !orders.contains(&uorder) || !orders.contains(&vorder) {
        return Err(GlError::InvalidValue);
    }
    let t = MapTarget::from_gl(target)
        .filter(|t| t.two_d)
        .ok_or(GlError::InvalidEnum)?;
    let k = t.kind.components();
    if ustride < k as i32 || vstride < k as i32 {
        return Err(GlError::InvalidValue);
    }
    Ok((
        t,
        (uorder as usize - 1) * ustride as usize + (vorder as usize - 1) * vstride as usize + k,
    ))
}

impl Evaluators {
    /// `glMap1f` (after [`check_map1`]): copies `order` points of the
    /// target's size, `stride` values apart, from `points`.
    pub fn map1(&mut self, t: MapTarget, u1: f32, u2: f32, stride: usize, order: usize, points: &[f32]) -> GlResult {
        let k = t.kind.components();
        let need = (order - 1) * stride + k;
        if t.two_d || order == 0 || order > MAX_EVAL_ORDER || stride < k || points.len() < need || u1 == u2 {
            return Err(GlError::InvalidValue);
        }
        let mut p = Vec::with_capacity(order * k);
        for i in 0..order {
            p.extend_from_slice(&points[i * stride..i * stride + k]);
        }
        self.map1[t.kind.index()] = Map1 {
            order,
            u1,
            u2,
            du: 1.0 / (u2 - u1),
            points: p,
        };
        Ok(())
    }

    /// `glMap2f` (after [`check_map2`]).
    #[allow(clippy::too_many_arguments)]
    pub fn map2(
        &mut self,
        t: MapTarget,
        (u1, u2, ustride, uorder): (f32, f32, usize, usize),
        (v1, v2, vstride, vorder): (f32, f32, usize, usize),
        points: &[f32],
    ) -> GlResult {
        let k = t.kind.components();
        let orders = 1..=MAX_EVAL_ORDER;
        if !t.two_d || !orders.contains(&uorder) || !orders.contains(&vorder) || ustride < k || vstride < k {
            return Err(GlError::InvalidValue);
        }
        if u1 == u2 || v1 == v2 || points.len() < (uorder - 1) * ustride + (vorder - 1) * vstride + k {
            return Err(GlError::InvalidValue);
        }
        let mut p = Vec::with_capacity(uorder * vorder * k);
        for i in 0..uorder {
            for j in 0..vorder {
                let o = i * ustride + j * vstride;
                p.extend_from_slice(&points[o..o + k]);
            }
        }
        self.map2[t.kind.index()] = Map2 {
            uorder,
            vorder,
            u1,
            u2,
            v1,
            v2,
            du: 1.0 / (u2 - u1),
            dv: 1.0 / (v2 - v1),
            points: p,
        };
        Ok(())
    }

    /// `glMapGrid1f`: `InvalidValue` for `un < 1`.
    pub fn map_grid1(&mut self, un: i32, u1: f32, u2: f32) -> GlResult {
        if un < 1 {
            return Err(GlError::InvalidValue);
        }
        let g = &mut self.grid;
        (g.un1, g.u1_1, g.u1_2, g.du1) = (un, u1, u2, (u2 - u1) / un as f32);
        Ok(())
    }

    /// `glMapGrid2f`: `InvalidValue` for `un < 1` or `vn < 1`.
    pub fn map_grid2(&mut self, un: i32, u1: f32, u2: f32, vn: i32, v1: f32, v2: f32) -> GlResult {
        if un < 1 || vn < 1 {
            return Err(GlError::InvalidValue);
        }
        let g = &mut self.grid;
        (g.un2, g.u2_1, g.u2_2, g.du2) = (un, u1, u2, (u2 - u1) / un as f32);
        (g.vn2, g.v2_1, g.v2_2, g.dv2) = (vn, v1, v2, (v2 - v1) / vn as f32);
        Ok(())
    }

    /// `glGetMap*v`: the values of `query` for `target`, as `f32`s (the
    /// integer query rounds them).
    pub fn get_map(&self, target: u32, query: u32) -> GlResult<Vec<f32>> {
        let t = MapTarget::from_gl(target).ok_or(GlError::InvalidEnum)?;
        let q = MapQuery::from_gl(query).ok_or(GlError::InvalidEnum)?;
        let i = t.kind.index();
        Ok(match (t.two_d, q) {
            (false, MapQuery::Coeff) => self.map1[i].points.clone(),
            (false, MapQuery::Order) => vec![self.map1[i].order as f32],
            (false, MapQuery::Domain) => vec![self.map1[i].u1, self.map1[i].u2],
            (true, MapQuery::Coeff) => self.map2[i].points.clone(),
            (true, MapQuery::Order) => vec![self.map2[i].uorder as f32, self.map2[i].vorder as f32],
            (true, MapQuery::Domain) => {
                let m = &self.map2[i];
                vec![m.u1, m.u2, m.v1, m.v2]
            }
        })
    }

    /// The attribute maps Mesa evaluates (`vbo_exec_eval_update`): colour,
    /// the largest texture map, normal; then the vertex map.
    fn attrib_maps(
        en: EvalEnables,
        enabled: impl Fn(EvalEnables, MapKind) -> bool,
    ) -> ([Option<MapKind>; 3], Option<MapKind>) {
        let on = |k| enabled(en, k).then_some(k);
        let tex = on(MapKind::Texture4)
            .or_else(|| on(MapKind::Texture3))
            .or_else(|| on(MapKind::Texture2))
            .or_else(|| on(MapKind::Texture1));
        let vertex = on(MapKind::Vertex4).or_else(|| on(MapKind::Vertex3));
        ([on(MapKind::Color4), tex, on(MapKind::Normal)], vertex)
    }

    /// `glEvalCoord1f`: inside `glBegin`/`glEnd`, with a vertex map
    /// enabled, a vertex whose enabled attributes are evaluated at `u`;
    /// the current values are left as they were.
    pub fn eval_coord1(&self, en: EvalEnables, gl: &mut Context, u: f32) {
        let (attribs, vertex) = Self::attrib_maps(en, EvalEnables::map1);
        let Some(vk) = vertex else { return };
        let saved = *gl.current();
        for k in attribs.into_iter().flatten() {
            let m = &self.map1[k.index()];
            let mut data = [0.0, 0.0, 0.0, 1.0];
            horner_bezier_curve(&m.points, &mut data, (u - m.u1) * m.du, k.components(), m.order);
            set_attrib(gl, k, data);
        }
        let m = &self.map1[vk.index()];
        let mut v = [0.0, 0.0, 0.0, 1.0];
        horner_bezier_curve(&m.points, &mut v, (u - m.u1) * m.du, vk.components(), m.order);
        emit(gl, vk, v);
        restore(gl, &saved, attribs);
    }

    /// `glEvalCoord2f`, with `GL_AUTO_NORMAL`'s normal for the vertex map.
    pub fn eval_coord2(&self, en: EvalEnables, gl: &mut Context, u: f32, v: f32) {
        let (mut attribs, vertex) = Self::attrib_maps(en, EvalEnables::map2);
        let Some(vk) = vertex else { return };
        let saved = *gl.current();
        for k in attribs.into_iter().flatten() {
            let m = &self.map2[k.index()];
            let mut data = [0.0, 0.0, 0.0, 1.0];
            let (uu, vv) = ((u - m.u1) * m.du, (v - m.v1) * m.dv);
            horner_bezier_surf(&m.points, &mut data, uu, vv, k.components(), m.uorder, m.vorder);
            set_attrib(gl, k, data);
        }
        let m = &self.map2[vk.index()];
        let (uu, vv) = ((u - m.u1) * m.du, (v - m.v1) * m.dv);
        let dim = vk.components();
        let mut vert = [0.0, 0.0, 0.0, 1.0];
        if en.0 & AUTO_NORMAL != 0 {
            let (mut du, mut dv) = ([0.0; 4], [0.0; 4]);
            de_casteljau_surf(&m.points, &mut vert, &mut du, &mut dv, uu, vv, dim, m.uorder, m.vorder);
            if dim == 4 {
                for c in 0..3 {
                    du[c] = du[c] * vert[3] - du[3] * vert[c];
                    dv[c] = dv[c] * vert[3] - dv[3] * vert[c];
                }
            }
            let mut n = [
                du[1] * dv[2] - du[2] * dv[1],
                du[2] * dv[0] - du[0] * dv[2],
                du[0] * dv[1] - du[1] * dv[0],
            ];
            let len = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
            if len != 0.0 {
                let inv = 1.0 / len.sqrt();
                for c in &mut n {
                    *c *= inv;
                }
            }
            gl.normal3(n[0], n[1], n[2]);
            attribs[2] = Some(MapKind::Normal);
        } else {
            horner_bezier_surf(&m.points, &mut vert, uu, vv, dim, m.uorder, m.vorder);
        }
        emit(gl, vk, vert);
        restore(gl, &saved, attribs);
    }

    /// `glEvalPoint1`: `glEvalCoord1` at grid point `i` (Mesa's arithmetic).
    pub fn eval_point1(&self, en: EvalEnables, gl: &mut Context, i: i32) {
        let g = &self.grid;
        let du = (g.u1_2 - g.u1_1) / g.un1 as f32;
        self.eval_coord1(en, gl, i as f32 * du + g.u1_1);
    }

    /// `glEvalPoint2`.
    pub fn eval_point2(&self, en: EvalEnables, gl: &mut Context, i: i32, j: i32) {
        let g = &self.grid;
        let du = (g.u2_2 - g.u2_1) / g.un2 as f32;
        let dv = (g.v2_2 - g.v2_1) / g.vn2 as f32;
        self.eval_coord2(en, gl, i as f32 * du + g.u2_1, j as f32 * dv + g.v2_1);
    }

    /// `glEvalMesh1`: points or a line strip through grid points
    /// `i1..=i2`; nothing without a vertex map. `Fill` is `InvalidEnum`.
    pub fn eval_mesh1(&self, en: EvalEnables, gl: &mut Context, mode: MeshMode, i1: i32, i2: i32) -> GlResult {
        if gl.inside_begin() {
            return Err(GlError::InvalidOperation);
        }
        let prim = match mode {
            MeshMode::Point => PrimitiveMode::Points,
            MeshMode::Line => PrimitiveMode::LineStrip,
            MeshMode::Fill => return Err(GlError::InvalidEnum),
        };
        if !en.map1(MapKind::Vertex3) && !en.map1(MapKind::Vertex4) {
            return Ok(());
        }
        let du = self.grid.du1;
        let mut u = self.grid.u1_1 + i1 as f32 * du;
        gl.begin(prim)?;
        for _ in i1..=i2 {
            self.eval_coord1(en, gl, u);
            u += du;
        }
        gl.end()
    }

    /// `glEvalMesh2`: points, line strips along `u` then along `v`, or
    /// triangle strips, over grid points `i1..=i2 × j1..=j2` (Mesa's
    /// `_mesa_EvalMesh2`, which accumulates `u += du`).
    #[allow(clippy::too_many_arguments)]
    pub fn eval_mesh2(
        &self,
        en: EvalEnables,
        gl: &mut Context,
        mode: MeshMode,
        i1: i32,
        i2: i32,
        j1: i32,
        j2: i32,
    ) -> GlResult {
        if gl.inside_begin() {
            return Err(GlError::InvalidOperation);
        }
        if !en.map2(MapKind::Vertex3) && !en.map2(MapKind::Vertex4) {
            return Ok(());
        }
        let g = &self.grid;
        let (du, dv) = (g.du2, g.dv2);
        let v1 = g.v2_1 + j1 as f32 * dv;
        let u1 = g.u2_1 + i1 as f32 * du;
        match mode {
            MeshMode::Point => {
                gl.begin(PrimitiveMode::Points)?;
                let mut v = v1;
                for _ in j1..=j2 {
                    let mut u = u1;
                    for _ in i1..=i2 {
                        self.eval_coord2(en, gl, u, v);
                        u += du;
                    }
                    v += dv;
                }
                gl.end()?;
            }
            MeshMode::Line => {
                let mut v = v1;
                for _ in j1..=j2 {
                    gl.begin(PrimitiveMode::LineStrip)?;
                    let mut u = u1;
                    for _ in i1..=i2 {
                        self.eval_coord2(en, gl, u, v);
                        u += du;
                    }
                    gl.end()?;
                    v += dv;
                }
                let mut u = u1;
                for _ in i1..=i2 {
                    gl.begin(PrimitiveMode::LineStrip)?;
                    let mut v = v1;
                    for _ in j1..=j2 {
                        self.eval_coord2(en, gl, u, v);
                        v += dv;
                    }
                    gl.end()?;
                    u += du;
                }
            }
            MeshMode::Fill => {
                let mut v = v1;
                for _ in j1..j2 {
                    gl.begin(PrimitiveMode::TriangleStrip)?;
                    let mut u = u1;
                    for _ in i1..=i2 {
                        self.eval_coord2(en, gl, u, v);
                        self.eval_coord2(en, gl, u, v + dv);
                        u += du;
                    }
                    gl.end()?;
                    v += dv;
                }
            }
        }
        Ok(())
    }
}

/// Sets the current value `k` from an evaluated `data` (`(x, 0, 0, 1)`
/// past the map's components, as Mesa's `COPY_SZ_4V` leaves them).
fn set_attrib(gl: &mut Context, k: MapKind, d: [f32; 4]) {
    match k {
        MapKind::Color4 => gl.color4(d[0], d[1], d[2], d[3]),
        MapKind::Normal => gl.normal3(d[0], d[1], d[2]),
        MapKind::Texture1 | MapKind::Texture2 | MapKind::Texture3 | MapKind::Texture4 => {
            gl.tex_coord4(d[0], d[1], d[2], d[3])
        }
        MapKind::Index | MapKind::Vertex3 | MapKind::Vertex4 => {}
    }
}

/// The evaluated vertex: `glVertex3fv` or `glVertex4fv` as in Mesa.
fn emit(gl: &mut Context, k: MapKind, v: [f32; 4]) {
    if k == MapKind::Vertex4 {
        gl.vertex4(v[0], v[1], v[2], v[3]);
    } else {
        gl.vertex3(v[0], v[1], v[2]);
    }
}

/// Puts back the current values evaluation changed (GL 1.5 §5.1: "the
/// current values are not updated"; Mesa copies the vertex back).
fn restore(gl: &mut Context, saved: &crate::context::CurrentAttribs, changed: [Option<MapKind>; 3]) {
    for k in changed.into_iter().flatten() {
        match k {
            MapKind::Color4 => {
                let c = saved.color;
                gl.color4(c.x, c.y, c.z, c.w);
            }
            MapKind::Normal => gl.normal3(saved.normal.x, saved.normal.y, saved.normal.z),
            MapKind::Texture1 | MapKind::Texture2 | MapKind::Texture3 | MapKind::Texture4 => {
                let t = saved.tex_coords[0];
                gl.tex_coord4(t.x, t.y, t.z, t.w);
            }
            MapKind::Index | MapKind::Vertex3 | MapKind::Vertex4 => {}
        }
    }
}

/// `1 / i` as Mesa's `inv_tab` holds it.
fn inv(i: usize) -> f32 {
    1.0 / i as f32
}

/// Mesa's `_math_horner_bezier_curve`: the point at `t` of the curve of
/// `order` control points of `dim` values in `cp`, into `out[..dim]`.
pub fn horner_bezier_curve(cp: &[f32], out: &mut [f32], t: f32, dim: usize, order: usize) {
    if order >= 2 {
        let mut bincoeff = (order - 1) as f32;
        let s = 1.0 - t;
        for k in 0..dim {
            out[k] = s * cp[k] + bincoeff * t * cp[dim + k];
        }
        let mut powert = t * t;
        let mut c = 2 * dim;
        for i in 2..order {
            bincoeff *= (order - i) as f32;
            bincoeff *= inv(i);
            for k in 0..dim {
                out[k] = s * out[k] + bincoeff * powert * cp[c + k];
            }
            powert *= t;
            c += dim;
        }
    } else {
        out[..dim].copy_from_slice(&cp[..dim]);
    }
}

/// Mesa's `_math_horner_bezier_surf`: the point at `(u, v)` of the surface
/// of `uorder × vorder` control points in `cn` (`v` fastest).
pub fn horner_bezier_surf(cn: &[f32], out: &mut [f32], u: f32, v: f32, dim: usize, uorder: usize, vorder: usize) {
    let uinc = vorder * dim;
    let mut cp = vec![0.0f32; uorder.max(vorder) * dim];
    if vorder > uorder {
        if uorder >= 2 {
            for j in 0..vorder {
                let mut ucp = j * dim;
                let mut bincoeff = (uorder - 1) as f32;
                let s = 1.0 - u;
                for k in 0..dim {
                    cp[j * dim + k] = s * cn[ucp + k] + bincoeff * u * cn[ucp + uinc + k];
                }
                ucp += 2 * uinc;
                let mut poweru = u * u;
                for i in 2..uorder {
                    bincoeff *= (uorder - i) as f32;
                    bincoeff *= inv(i);
                    for k in 0..dim {
                        cp[j * dim + k] = s * cp[j * dim + k] + bincoeff * poweru * cn[ucp + k];
                    }
                    poweru *= u;
                    ucp += uinc;
                }
            }
            horner_bezier_curve(&cp, out, v, dim, vorder);
        } else {
            horner_bezier_curve(cn, out, v, dim, vorder);
        }
    } else if vorder > 1 {
        for i in 0..uorder {
            let (o, row) = (&mut cp[i * dim..], &cn[i * uinc..]);
            horner_bezier_curve(row, o, v, dim, vorder);
        }
        horner_bezier_curve(&cp, out, u, dim, uorder);
    } else {
        horner_bezier_curve(cn, out, u, dim, uorder);
    }
}

/// Mesa's `_math_de_casteljau_surf`: the point at `(u, v)` and the
/// derivative directions `du`, `dv` (for `GL_AUTO_NORMAL`).
#[allow(clippy::too_many_arguments)]
pub fn de_casteljau_surf(
    cn: &[f32],
    out: &mut [f32],
    du: &mut [f32],
    dv: &mut [f32],
    u: f32,
    v: f32,
    dim: usize,
    uorder: usize,
    vorder: usize,
) {
    let (us, vs) = (1.0 - u, 1.0 - v);
    let minorder = uorder.min(vorder);
    let uinc = vorder * dim;
    let dcuinc = vorder;
    let cnk = |i: usize, j: usize, k: usize| cn[i * uinc + j * dim + k];
    // Mesa's scratch space after the points: (uorder, vorder) values, with
    // room for the third column the last equal-order step writes.
    let mut dcn = vec![0.0f32; uorder.max(3) * vorder.max(3)];
    macro_rules! d {
        ($i:expr, $j:expr) => {
            dcn[($i) * dcuinc + ($j)]
        };
    }
    if minorder < 3 {
        if uorder == vorder {
            for k in 0..dim {
                du[k] = vs * (cnk(1, 0, k) - cnk(0, 0, k)) + v * (cnk(1, 1, k) - cnk(0, 1, k));
                dv[k] = us * (cnk(0, 1, k) - cnk(0, 0, k)) + u * (cnk(1, 1, k) - cnk(1, 0, k));
                out[k] = us * (vs * cnk(0, 0, k) + v * cnk(0, 1, k)) + u * (vs * cnk(1, 0, k) + v * cnk(1, 1, k));
            }
        } else if minorder == uorder {
            for k in 0..dim {
                d!(1, 0) = cnk(1, 0, k) - cnk(0, 0, k);
                d!(0, 0) = us * cnk(0, 0, k) + u * cnk(1, 0, k);
                for j in 0..vorder - 1 {
                    d!(1, j + 1) = cnk(1, j + 1, k) - cnk(0, j + 1, k);
                    d!(1, j) = vs * d!(1, j) + v * d!(1, j + 1);
                    d!(0, j + 1) = us * cnk(0, j + 1, k) + u * cnk(1, j + 1, k);
                    d!(0, j) = vs * d!(0, j) + v * d!(0, j + 1);
                }
                for h in minorder..vorder - 1 {
                    for j in 0..vorder - h {
                        d!(1, j) = vs * d!(1, j) + v * d!(1, j + 1);
                        d!(0, j) = vs * d!(0, j) + v * d!(0, j + 1);
                    }
                }
                dv[k] = d!(0, 1) - d!(0, 0);
                du[k] = vs * d!(1, 0) + v * d!(1, 1);
                out[k] = vs * d!(0, 0) + v * d!(0, 1);
            }
        } else {
            for k in 0..dim {
                d!(0, 1) = cnk(0, 1, k) - cnk(0, 0, k);
                d!(0, 0) = vs * cnk(0, 0, k) + v * cnk(0, 1, k);
                for i in 0..uorder - 1 {
                    d!(i + 1, 1) = cnk(i + 1, 1, k) - cnk(i + 1, 0, k);
                    d!(i, 1) = us * d!(i, 1) + u * d!(i + 1, 1);
                    d!(i + 1, 0) = vs * cnk(i + 1, 0, k) + v * cnk(i + 1, 1, k);
                    d!(i, 0) = us * d!(i, 0) + u * d!(i + 1, 0);
                }
                for h in minorder..uorder - 1 {
                    for i in 0..uorder - h {
                        d!(i, 1) = us * d!(i, 1) + u * d!(i + 1, 1);
                        d!(i, 0) = us * d!(i, 0) + u * d!(i + 1, 0);
                    }
                }
                du[k] = d!(1, 0) - d!(0, 0);
                dv[k] = us * d!(0, 1) + u * d!(1, 1);
                out[k] = us * d!(0, 0) + u * d!(1, 0);
            }
        }
    } else {
        for k in 0..dim {
            // Both directions reduced together down to order 2 in the smaller one.
            for i in 0..uorder - 1 {
                d!(i, 0) = us * cnk(i, 0, k) + u * cnk(i + 1, 0, k);
                for j in 0..vorder - 1 {
                    d!(i, j + 1) = us * cnk(i, j + 1, k) + u * cnk(i + 1, j + 1, k);
                    d!(i, j) = vs * d!(i, j) + v * d!(i, j + 1);
                }
            }
            for h in 2..minorder - 1 {
                for i in 0..uorder - h {
                    d!(i, 0) = us * d!(i, 0) + u * d!(i + 1, 0);
                    for j in 0..vorder - h {
                        d!(i, j + 1) = us * d!(i, j + 1) + u * d!(i + 1, j + 1);
                        d!(i, j) = vs * d!(i, j) + v * d!(i, j + 1);
                    }
                }
            }
            if uorder == vorder {
                du[k] = vs * (d!(1, 0) - d!(0, 0)) + v * (d!(1, 1) - d!(0, 1));
                dv[k] = us * (d!(0, 1) - d!(0, 0)) + u * (d!(1, 1) - d!(1, 0));
                out[k] = us * (vs * d!(0, 0) + v * d!(0, 1)) + u * (vs * d!(1, 0) + v * d!(1, 1));
            } else if minorder == uorder {
                d!(2, 0) = d!(1, 0) - d!(0, 0);
                d!(0, 0) = us * d!(0, 0) + u * d!(1, 0);
                for j in 0..vorder - 1 {
                    d!(2, j + 1) = d!(1, j + 1) - d!(0, j + 1);
                    d!(2, j) = vs * d!(2, j) + v * d!(2, j + 1);
                    d!(0, j + 1) = us * d!(0, j + 1) + u * d!(1, j + 1);
                    d!(0, j) = vs * d!(0, j) + v * d!(0, j + 1);
                }
                for h in minorder..vorder - 1 {
                    for j in 0..vorder - h {
                        d!(2, j) = vs * d!(2, j) + v * d!(2, j + 1);
                        d!(0, j) = vs * d!(0, j) + v * d!(0, j + 1);
                    }
                }
                dv[k] = d!(0, 1) - d!(0, 0);
                du[k] = vs * d!(2, 0) + v * d!(2, 1);
                out[k] = vs * d!(0, 0) + v * d!(0, 1);
            } else {
                d!(0, 2) = d!(0, 1) - d!(0, 0);
                d!(0, 0) = vs * d!(0, 0) + v * d!(0, 1);
                for i in 0..uorder - 1 {
                    d!(i + 1, 2) = d!(i + 1, 1) - d!(i + 1, 0);
                    d!(i, 2) = us * d!(i, 2) + u * d!(i + 1, 2);
                    d!(i + 1, 0) = vs * d!(i + 1, 0) + v * d!(i + 1, 1);
                    d!(i, 0) = us * d!(i, 0) + u * d!(i + 1, 0);
                }
                for h in minorder..uorder - 1 {
                    for i in 0..uorder - h {
                        d!(i, 2) = us * d!(i, 2) + u * d!(i + 1, 2);
                        d!(i, 0) = us * d!(i, 0) + u * d!(i + 1, 0);
                    }
                }
                du[k] = d!(1, 0) - d!(0, 0);
                dv[k] = us * d!(0, 2) + u * d!(1, 2);
                out[k] = us * d!(0, 0) + u * d!(1, 0);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MAP1_VERTEX_3: u32 = 0x0D97;
    const MAP2_VERTEX_3: u32 = 0x0DB7;

    #[test]
    fn cubic_curve_matches_bernstein_at_exact_points() {
        // Control points 0, 3, 6, 9 on x: the curve is x = 9t (a
        // degree-elevated line), exact at dyadic t.
        let cp = [0.0, 0.0, 3.0, 1.0, 6.0, 2.0, 9.0, 3.0];
        let mut out = [0.0; 2];
        for (t, x) in [(0.0, 0.0), (0.25, 2.25), (0.5, 4.5), (1.0, 9.0)] {
            horner_bezier_curve(&cp, &mut out, t, 2, 4);
            assert_eq!(out, [x, x / 3.0]);
        }
        // Order 1: the constant point.
        horner_bezier_curve(&[7.0, 8.0], &mut out, 0.3, 2, 1);
        assert_eq!(out, [7.0, 8.0]);
    }

    #[test]
    fn surface_and_de_casteljau_agree_on_a_bilinear_patch() {
        // z = u * v over the unit square (control points exact in binary).
        for (uo, vo) in [(2, 2), (2, 3), (3, 2), (3, 3), (3, 5), (5, 3), (5, 5), (2, 5)] {
            let mut cn = Vec::new();
            for i in 0..uo {
                for j in 0..vo {
                    let (x, y) = (i as f32 / (uo - 1) as f32, j as f32 / (vo - 1) as f32);
                    cn.extend_from_slice(&[x, y, x * y]);
                }
            }
            let (mut a, mut b, mut du, mut dv) = ([0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3]);
            horner_bezier_surf(&cn, &mut a, 0.5, 0.25, 3, uo, vo);
            de_casteljau_surf(&cn, &mut b, &mut du, &mut dv, 0.5, 0.25, 3, uo, vo);
            assert_eq!(a, [0.5, 0.25, 0.125], "{uo}x{vo}");
            assert_eq!(b, [0.5, 0.25, 0.125], "{uo}x{vo}");
            // d/du = (1, 0, v), d/dv = (0, 1, u), scaled by the degree.
            let (su, sv) = ((uo - 1) as f32, (vo - 1) as f32);
            assert_eq!(du, [1.0 / su, 0.0, 0.25 / su], "{uo}x{vo}");
            assert_eq!(dv, [0.0, 1.0 / sv, 0.5 / sv], "{uo}x{vo}");
        }
    }

    #[test]
    fn map_errors_in_mesas_order() {
        let p = [0.0f32; 12];
        assert_eq!(check_map1(MAP1_VERTEX_3, 1.0, 1.0, 3, 2), Err(GlError::InvalidValue));
        assert_eq!(check_map1(MAP1_VERTEX_3, 0.0, 1.0, 3, 0), Err(GlError::InvalidValue));
        assert_eq!(check_map1(MAP1_VERTEX_3, 0.0, 1.0, 3, 31), Err(GlError::InvalidValue));
        assert_eq!(check_map1(0x0DB7, 0.0, 1.0, 3, 2), Err(GlError::InvalidEnum));
        assert_eq!(check_map1(MAP1_VERTEX_3, 0.0, 1.0, 2, 2), Err(GlError::InvalidValue));
        let (t, n) = check_map1(MAP1_VERTEX_3, 0.0, 1.0, 4, 3).unwrap();
        assert_eq!(n, 11);
        let mut e = Evaluators::default();
        e.map1(t, 0.0, 1.0, 4, 3, &p[..11]).unwrap();
        assert_eq!(e.map1(t, 0.0, 1.0, 4, 3, &p[..10]), Err(GlError::InvalidValue));
        assert_eq!(
            check_map2(MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 2, 2),
            Err(GlError::InvalidValue)
        );
        assert_eq!(
            check_map2(MAP1_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 3, 2),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(check_map2(MAP2_VERTEX_3, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2).unwrap().1, 12);
    }

    #[test]
    fn map_copies_strided_points_and_get_map_reads_them() {
        let mut e = Evaluators::default();
        assert_eq!(e.get_map(0x0D90, 0x0A00).unwrap(), vec![1.0; 4]);
        assert_eq!(e.get_map(0x0DB7, 0x0A01).unwrap(), vec![1.0, 1.0]);
        assert_eq!(e.get_map(0x0DB7, 0x0A02).unwrap(), vec![0.0, 1.0, 0.0, 1.0]);
        let pts: Vec<f32> = (0..16).map(|i| i as f32).collect();
        // 2 × 2 points of 3 values: ustride 8, vstride 4 (one value skipped).
        let (t, n) = check_map2(MAP2_VERTEX_3, 2.0, 4.0, 8, 2, -1.0, 1.0, 4, 2).unwrap();
        e.map2(t, (2.0, 4.0, 8, 2), (-1.0, 1.0, 4, 2), &pts[..n]).unwrap();
        let want = [0.0, 1.0, 2.0, 4.0, 5.0, 6.0, 8.0, 9.0, 10.0, 12.0, 13.0, 14.0];
        assert_eq!(e.get_map(MAP2_VERTEX_3, 0x0A00).unwrap(), want);
        assert_eq!(e.get_map(MAP2_VERTEX_3, 0x0A01).unwrap(), vec![2.0, 2.0]);
        assert_eq!(e.get_map(MAP2_VERTEX_3, 0x0A02).unwrap(), vec![2.0, 4.0, -1.0, 1.0]);
        assert_eq!(e.get_map(0x0D80, 0x0A00), Err(GlError::InvalidEnum));
        assert_eq!(e.get_map(MAP2_VERTEX_3, 0x0A03), Err(GlError::InvalidEnum));
    }

    #[test]
    fn grids() {
        let mut e = Evaluators::default();
        assert_eq!(e.map_grid1(0, 0.0, 1.0), Err(GlError::InvalidValue));
        assert_eq!(e.map_grid2(1, 0.0, 1.0, 0, 0.0, 1.0), Err(GlError::InvalidValue));
        e.map_grid2(4, 0.0, 1.0, 2, 1.0, 0.0).unwrap();
        assert_eq!((e.grid.un2, e.grid.du2, e.grid.vn2, e.grid.dv2), (4, 0.25, 2, -0.5));
    }
}
