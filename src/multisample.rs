//! 4× multisampling as llvmpipe does it (`docs/llvmpipe-facts.md` §29): a
//! multisampled framebuffer is one single-sampled framebuffer per sample
//! (sample 0 the framebuffer itself, samples 1.. in `Framebuffer::samples`).
//! A draw into it is recorded once per sample, into a scene of its own
//! (`context.rs`, "lanes"), with the triangle's coverage tested at that
//! sample's position and its depth evaluated there; every other attribute
//! is interpolated at the pixel centre, as llvmpipe's fragment shader runs
//! once per pixel. The samples are independent (each sees the same
//! fragments in the same order, tested against its own depth and stencil,
//! blended with its own colour), so drawing them apart gives the bytes of
//! drawing them together. [`Framebuffer::resolve`] averages them as
//! `glBlitFramebuffer` does on llvmpipe.
//!
//! The shading of the four samples is then the same computation four times
//! (interpolation, texturing, texture environment, fog, alpha test), and
//! for MuJoCo's light passes (two texture units, one a 4096² shadow map
//! with compare) it was most of the frame. With `GL_MULTISAMPLE` on, a
//! draw whose key splits ([`shared_halves`], `FragmentKey::split_shading`)
//! is recorded once for all four samples instead ([`SharedFan`]): each
//! triangle's four coverages and depth planes in one record of the
//! context's own scene, which then records (and flushes) for every sample
//! (`Context::share_samples`; draws that do not split, alpha to coverage,
//! `GL_MULTISAMPLE` off, polygon stipple, pixel rectangles and bitmaps go
//! to the lanes as before, the pending draws rasterized first when the
//! mode changes so that each sample's draws keep their order). A tile runs
//! such a triangle's shading half once over the pixels any sample covers
//! (and may pass the stencil and depth tests, tested early),
//! then its per-sample half for each sample over its own covered pixels
//! among those the shading kept (`raster::scene`, `Scene::run_group`): the
//! bytes of the per-sample draws (`tests/msaa_shared.rs` draws random
//! scenes both ways; `jit/tests/contract.rs`, `split_keys_equal_the_whole`).

use crate::error::{GlError, GlResult};
use crate::framebuffer::{rint_nonnegative, DepthBuffer, Framebuffer, FramebufferDesc};
use crate::geometry::varying::Varyings;
use crate::raster::scene::{Binner, DrawState};
use crate::raster::{PrimSink, RasterParams, RasterVertex};
use softgl_jit::{deep, pixel, ColorFormat, DepthTarget, FragmentKey};

/// `GL_MAX_SAMPLES`: llvmpipe supports 1 and 4 samples (`lp_screen.c`,
/// `llvmpipe_is_format_supported`).
pub const MAX_SAMPLES: u32 = 4;

/// llvmpipe's 4× sample positions within a pixel (`lp_sample_pos_4x`,
/// `lp_rast.c`), x right and y up from the pixel's lower-left corner in a
/// framebuffer object (its rows are not flipped: y grows with GL's y).
pub const SAMPLE_POSITIONS_4X: [(f32, f32); 4] = [(0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)];

/// Where one sample of a multisampled framebuffer is tested: its offset from
/// the pixel centre, in the rasterizer's fixed point (bottom-up, 8 sub-pixel
/// bits: exact, the positions being multiples of 1/8) and in the attribute
/// planes' frame (x right, y down), where depth is evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleAt {
    pub fixed: (i64, i64),
    pub plane: (f32, f32),
}

impl SampleAt {
    /// Sample `s` (below 4) of llvmpipe's 4× pattern in a framebuffer object.
    pub fn of_4x(s: usize) -> SampleAt {
        SampleAt::of_4x_in(s, false)
    }

    /// Sample `s` (below 4) of llvmpipe's 4× pattern, in a window's buffer
    /// when `window`: llvmpipe's rows run top-down there (a window system
    /// framebuffer is `Y_0_TOP`, `st_atom_framebuffer.c`) and the pattern,
    /// placed along its rows, is mirrored in GL's y (`docs/llvmpipe-facts.md` §40).
    pub fn of_4x_in(s: usize, window: bool) -> SampleAt {
        let (x, y) = SAMPLE_POSITIONS_4X[s];
        let y = if window { 1.0 - y } else { y };
        let one = crate::raster::ONE as f32;
        SampleAt {
            fixed: (((x - 0.5) * one) as i64, ((y - 0.5) * one) as i64),
            plane: (x - 0.5, 0.5 - y),
        }
    }
}

/// The samples a pixel of a renderbuffer `glRenderbufferStorageMultisample`
/// asks `requested` of gets, as Mesa picks them for llvmpipe
/// (`st_renderbuffer_alloc_storage`: the least supported count from
/// `max(2, requested)`; probed, `docs/probes/multisample/samples.c`): 0 is
/// one sample (`GL_RENDERBUFFER_SAMPLES` 0), 1 to 4 are 4; more than
/// [`MAX_SAMPLES`] is `GL_INVALID_OPERATION` (Mesa's, measured), a negative
/// count `GL_INVALID_VALUE`.
pub fn renderbuffer_samples(requested: i32) -> GlResult<u32> {
    match requested {
        r if r < 0 => Err(GlError::InvalidValue),
        0 => Ok(1),
        r if r as u32 <= MAX_SAMPLES => Ok(MAX_SAMPLES),
        _ => Err(GlError::InvalidOperation),
    }
}

/// The samples `glSampleCoverage(value, invert)` keeps, as llvmpipe's state
/// tracker makes the mask (`st_update_sample_state`, `st_atom_msaa.c`): the
/// first `(unsigned)(value · samples)` samples (f32 product, truncated),
/// complemented when `invert`.
pub fn sample_coverage_mask(value: f32, invert: bool, samples: u32) -> u32 {
    let value = if value.is_nan() { 0.0 } else { value.clamp(0.0, 1.0) };
    let bits = (value * samples as f32) as u32;
    let mask = if bits >= 32 { u32::MAX } else { (1u32 << bits) - 1 };
    if invert {
        !mask
    } else {
        mask
    }
}

/// Hands each primitive to the scene of each sample a draw writes
/// (`Context::draw_with`): with `GL_MULTISAMPLE` on, triangles covered at
/// the sample's position, lines as llvmpipe's rectangles and points as its
/// squares, covered the same way; with it off, every primitive as at one
/// sample a pixel (the same fragments in every sample).
#[derive(Default)]
pub(crate) struct Fan<'s> {
    pub(crate) lanes: Vec<(Binner<'s>, Option<SampleAt>)>,
}

impl Fan<'_> {
    /// Ends the draw in every sample: the first error of a flush.
    pub(crate) fn finish(self) -> Result<(), softgl_jit::FragmentError> {
        self.lanes
            .into_iter()
            .map(|(b, _)| b.finish())
            .fold(Ok(()), Result::and)
    }
}

impl PrimSink for Fan<'_> {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        for (b, at) in &mut self.lanes {
            b.triangle_at(v, flat, params, at.as_ref());
        }
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        let quad = match self.lanes.first() {
            Some((_, Some(_))) => line_rectangle(a, b, width, params),
            _ => None,
        };
        for (sink, at) in &mut self.lanes {
            match (&quad, at.as_ref()) {
                (Some((p, v)), Some(at)) => {
                    let params = RasterParams {
                        offset: None,
                        ..*params
                    };
                    sink.triangle_points([p[0], p[1], p[2]], [&v[0], &v[1], &v[2]], flat, &params, Some(at));
                    sink.triangle_points([p[0], p[2], p[3]], [&v[0], &v[2], &v[3]], flat, &params, Some(at));
                }
                (None, Some(_)) => {}
                (_, None) => sink.line(a, b, width, flat, params),
            }
        }
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        let square = match self.lanes.first() {
            Some((_, Some(_))) => point_square(v, size, params),
            _ => None,
        };
        for (sink, at) in &mut self.lanes {
            match (&square, at.as_ref()) {
                (Some((p, c)), Some(at)) => {
                    let params = RasterParams {
                        offset: None,
                        ..*params
                    };
                    sink.triangle_points([p[0], p[1], p[2]], [&c[0], &c[1], &c[2]], None, &params, Some(at));
                    sink.triangle_points([p[0], p[2], p[3]], [&c[0], &c[2], &c[3]], None, &params, Some(at));
                }
                (None, Some(_)) => {}
                (_, None) => sink.point(v, size, params),
            }
        }
    }
}

/// Whether the draw of `key` into a 4× framebuffer with `GL_MULTISAMPLE`
/// on (and no polygon stipple) shares its shading between the samples
/// ([`shared_halves`]): a key that can be split and writes colour (one
/// that writes none shades for its alpha test at most, which each
/// sample's specialist does cheaply without the colour).
pub(crate) fn shares_shading(key: &FragmentKey) -> bool {
    // Cube maps stay per sample: MuJoCo's skybox, a cylinder around the
    // camera drawn last, is hidden but for a few hundred pixels, which the
    // per-sample specialists' depth tests find cheaply. Shared, the early
    // tests (`raster::scene::EarlyTests`) test every sample of the whole
    // screen: the `noshadow` frame took 1.249 G → 1.427 G instructions
    // (640×480, two frames, callgrind), with the early tests 0.10 → 0.34 G
    // and the sampling unchanged (1,405 lanes). (They had let every hidden
    // pixel through before on MuJoCo's D32F buffer, whose margin was 2.0;
    // docs/mujoco.md, the `texnative` section.)
    let cube = key.shade.is_some_and(|s| {
        s.tex
            .iter()
            .flatten()
            .any(|u| u.sampler.target == softgl_jit::texture::TexTarget::Cube)
    });
    !cube && key.split_shading().is_some() && !key.color_mask.writes_nothing(key.color_format)
}

/// A draw whose samples share its shading, split as llvmpipe runs it (the
/// fragment shader once a pixel, the per-sample tests and writes after
/// it; [`FragmentKey::split_shading`]): its shading half, run into a
/// band's RGBA8 and stencil target, and its per-sample half, run for each
/// sample on the fragments the first kept, with their colours. The bytes
/// are those of the whole key run per sample: the shading reads no buffer
/// and gives each sample the same colour (all attributes but depth are
/// interpolated at the pixel centre), and the unorm8 colour is what the
/// stages after it read either way (the alpha test too: it compares
/// bytes). `specialist` gives a key's specialist, if any.
pub(crate) fn shared_halves(
    state: &DrawState,
    mut specialist: impl FnMut(&FragmentKey) -> Option<std::sync::Arc<softgl_jit::Specialist>>,
) -> Option<(DrawState, DrawState)> {
    let (shade_key, ops_key) = state.key.split_shading()?;
    let shading = DrawState {
        key: shade_key,
        uniforms: state.uniforms.shading_half(),
        specialist: specialist(&shade_key),
        textures: state.textures.clone(),
        samples: None,
        polygon_stipple: None,
        shades_samples: true,
    };
    let ops = DrawState {
        key: ops_key,
        uniforms: state.uniforms,
        specialist: specialist(&ops_key),
        textures: Default::default(),
        samples: state.samples.clone(),
        polygon_stipple: None,
        shades_samples: false,
    };
    Some((shading, ops))
}

/// Hands each primitive of a draw whose samples share the shading to one
/// scene, for every sample at once ([`Binner::triangle_shared`]): with
/// `GL_MULTISAMPLE` on, triangles, and lines and points as the rectangles
/// and squares [`Fan`] gives each sample, covered at each sample kept by
/// `mask` (`glSampleCoverage`).
pub(crate) struct SharedFan<'s> {
    pub(crate) binner: Binner<'s>,
    pub(crate) at: [SampleAt; 4],
    pub(crate) mask: u32,
}

impl SharedFan<'_> {
    /// Ends the draw: the first error of a flush.
    pub(crate) fn finish(self) -> Result<(), softgl_jit::FragmentError> {
        self.binner.finish()
    }

    fn quad(&mut self, (p, v): &Corners, flat: Option<&Varyings>, params: &RasterParams) {
        let params = RasterParams {
            offset: None,
            ..*params
        };
        let (at, mask) = (&self.at, self.mask);
        let b = &mut self.binner;
        b.triangle_shared([p[0], p[1], p[2]], [&v[0], &v[1], &v[2]], flat, &params, (at, mask));
        b.triangle_shared([p[0], p[2], p[3]], [&v[0], &v[2], &v[3]], flat, &params, (at, mask));
    }
}

impl PrimSink for SharedFan<'_> {
    fn triangle(&mut self, v: [&RasterVertex; 3], flat: Option<&Varyings>, params: &RasterParams) {
        let p = crate::raster::Edges::window_points(v, params.height);
        self.binner.triangle_shared(p, v, flat, params, (&self.at, self.mask));
    }

    fn line(&mut self, a: &RasterVertex, b: &RasterVertex, width: f32, flat: Option<&Varyings>, params: &RasterParams) {
        if let Some(q) = line_rectangle(a, b, width, params) {
            self.quad(&q, flat, params);
        }
    }

    fn point(&mut self, v: &RasterVertex, size: f32, params: &RasterParams) {
        if let Some(q) = point_square(v, size, params) {
            self.quad(&q, None, params);
        }
    }
}

/// A quad's corners: snapped points in softgl's frame, and vertices with
/// their attributes for the plane set-up.
type Corners = ([(i64, i64); 4], [RasterVertex; 4]);

/// The rectangle llvmpipe covers for a multisampled line `a → b`
/// (`try_setup_line`, `lp_setup_line.c`, `rectangular_lines`): the
/// endpoints snapped (no pixel offset), moved by `±t`, the snapped normal
/// `(−dy, dx) · (width / 2) / |d|` with `d = a − b`, in the order
/// `a − t, b − t, b + t, a + t`, covered by the triangle rule as two
/// triangles (whose shared diagonal owns each sample once); `width`
/// clamped to llvmpipe's `[1, 255]`. The corners' points in softgl's
/// snapped bottom-up frame, and vertices carrying their endpoint's
/// attributes for the planes. `None` for a zero-length or non-finite line.
fn line_rectangle(a: &RasterVertex, b: &RasterVertex, width: f32, params: &RasterParams) -> Option<Corners> {
    let (dx, dy) = (a.x - b.x, a.y - b.y);
    let area = dx * dx + dy * dy;
    if !(area.is_finite() && area > 0.0) {
        return None;
    }
    let width = if width.is_nan() { 1.0 } else { width.clamp(1.0, 255.0) };
    let scale = (width * 0.5) / area.sqrt();
    let (tx, ty) = (subpixel_snap(-dy * scale), subpixel_snap(dx * scale));
    // No pixel offset; moved to softgl's frame, whose integers are pixel centres.
    let at = |v: &RasterVertex| (subpixel_snap(v.x) - 128, subpixel_snap(v.y) - 128);
    let (pa, pb) = (at(a), at(b));
    let p = [
        (pa.0 - tx, pa.1 - ty),
        (pb.0 - tx, pb.1 - ty),
        (pb.0 + tx, pb.1 + ty),
        (pa.0 + tx, pa.1 + ty),
    ];
    let v = [
        corner(a, p[0], params),
        corner(b, p[1], params),
        corner(b, p[2], params),
        corner(a, p[3], params),
    ];
    Some((p, v))
}

/// `subpixel_snap` of `lp_setup_line.c` and `lp_setup_point.c`:
/// `util_iround(256 · v)`, half away from zero in f32 (x86-64's
/// `util_iround`, `u_math.h`).
fn subpixel_snap(v: f32) -> i64 {
    let f = crate::raster::ONE as f32 * v;
    if f >= 0.0 {
        (f + 0.5) as i64
    } else {
        (f - 0.5) as i64
    }
}

/// The square llvmpipe covers for a multisampled point (`try_setup_point`,
/// `lp_setup_point.c`, not `legacy_points`): side `max(256,
/// subpixel_snap(size))` (size at most 255), from the snapped centre (no
/// pixel offset) minus half the side, its left and bottom edges owned, as
/// two triangles; corners in softgl's frame and vertices with the point's
/// attributes. `None` for a non-finite position.
fn point_square(v: &RasterVertex, size: f32, params: &RasterParams) -> Option<Corners> {
    if !(v.x.is_finite() && v.y.is_finite()) {
        return None;
    }
    let size = if size.is_nan() { 1.0 } else { size.clamp(0.0, 255.0) };
    let side = subpixel_snap(size).max(crate::raster::ONE);
    let (x0, y0) = (subpixel_snap(v.x) - side / 2 - 128, subpixel_snap(v.y) - side / 2 - 128);
    let p = [(x0, y0), (x0 + side, y0), (x0 + side, y0 + side), (x0, y0 + side)];
    Some((p, p.map(|q| corner(v, q, params))))
}

/// A vertex at the snapped point `q` (softgl's frame) with `from`'s
/// attributes, for the plane set-up of a line's or a point's corners.
fn corner(from: &RasterVertex, (x, y): (i64, i64), params: &RasterParams) -> RasterVertex {
    let one = crate::raster::ONE as f32;
    let (x, y) = ((x as f32 + 128.0) / one, (y as f32 + 128.0) / one);
    RasterVertex {
        x,
        y,
        y_down: params.height as f32 - y,
        ..*from
    }
}

impl Framebuffer {
    /// A framebuffer of `samples` samples a pixel (1 or 4: `InvalidValue`
    /// otherwise), each cleared as [`Framebuffer::new`] clears.
    pub fn new_multisample(desc: FramebufferDesc, samples: u32) -> GlResult<Framebuffer> {
        if !matches!(samples, 1 | MAX_SAMPLES) {
            return Err(GlError::InvalidValue);
        }
        let mut fb = Framebuffer::new(desc)?;
        for _ in 1..samples {
            fb.samples.push(Framebuffer::new(desc)?);
        }
        Ok(fb)
    }

    /// A window's multisampled buffer (an EGL surface of a config with
    /// `EGL_SAMPLES` 4): as [`Framebuffer::new_multisample`], its samples
    /// placed as in llvmpipe's window buffers ([`SampleAt::of_4x_in`]).
    pub fn new_multisample_window(desc: FramebufferDesc, samples: u32) -> GlResult<Framebuffer> {
        let mut fb = Framebuffer::new_multisample(desc, samples)?;
        fb.window_samples = true;
        Ok(fb)
    }

    /// Samples a pixel: 1, or 4 for a multisampled framebuffer.
    pub fn samples(&self) -> u32 {
        1 + self.samples.len() as u32
    }

    /// Sample `s`'s buffers as a single-sampled framebuffer (sample 0 is
    /// this one's own buffers, read with the accessors that ignore the
    /// other samples: [`Framebuffer::pixel`], [`Framebuffer::depth_at`], …).
    pub fn sample(&self, s: u32) -> Option<&Framebuffer> {
        match s {
            0 => Some(self),
            s => self.samples.get(s as usize - 1),
        }
    }

    /// Sample `s`'s buffers, to write (a blit into a multisampled
    /// framebuffer writes each sample). Sample 0 is this framebuffer: its
    /// own buffers through [`Framebuffer::target`] and the like.
    pub fn sample_mut(&mut self, s: u32) -> Option<&mut Framebuffer> {
        match s {
            0 => Some(self),
            s => self.samples.get_mut(s as usize - 1),
        }
    }

    /// The colour at `(x, y)` of sample `s`, as [`Framebuffer::pixel`].
    pub fn sample_pixel(&self, x: u32, y: u32, s: u32) -> Option<[u8; 4]> {
        self.sample(s)?.pixel(x, y)
    }

    /// This framebuffer resolved to one sample a pixel, as llvmpipe's
    /// `glBlitFramebuffer` resolves (`util_make_fs_msaa_resolve`,
    /// `u_simple_shaders.c`): each colour channel the f32 sum of the
    /// samples' unorm values times `1/max` (`lp_build_unsigned_norm_to_float`),
    /// in sample order, times 0.25, then `rint(v · max)` as any fragment
    /// colour; depth and stencil are sample 0's (`util_make_fs_blit_msaa_gen`
    /// fetches sample 0 when the destination has one). A single-sampled
    /// framebuffer resolves to a copy. The result owns its colour bytes,
    /// rows bottom-up and tightly packed.
    pub fn resolve(&self) -> GlResult<Framebuffer> {
        self.resolve_for(self.desc().color)
    }

    /// [`Framebuffer::resolve`] for a blit into a `target` colour format:
    /// where a deep format is on either side and the formats differ, the
    /// colour is resolved into RGBA32F, unrounded, for the blit to store as
    /// the destination's fragment colour (llvmpipe's resolve shader writes
    /// the destination directly).
    pub fn resolve_for(&self, target: ColorFormat) -> GlResult<Framebuffer> {
        let mut desc = *self.desc();
        let from = desc.color;
        if from != target && (from.is_deep() || target.is_deep()) {
            desc.color = ColorFormat::Rgba32F;
        }
        let mut out = Framebuffer::new(desc)?;
        let format = desc.color;
        let bpp = format.bytes_per_pixel();
        {
            let mut t = out.target();
            let eight_bits = matches!(format, ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8);
            let row_bytes = desc.width as usize * bpp;
            let mut packed = Vec::with_capacity(self.samples() as usize);
            for y in 0..desc.height {
                let o = t.color_offset(0, y);
                let dst = &mut t.color_mut()[o..o + row_bytes];
                if eight_bits && self.samples() == 4 {
                    let row = |s: u32| {
                        let fb = self.sample(s).expect("s < samples");
                        &fb.color_bytes()[fb.color_offset(0, y)..][..row_bytes]
                    };
                    resolve_row_4x8(dst, [row(0), row(1), row(2), row(3)]);
                    continue;
                }
                if format.is_deep() {
                    resolve_row_deep(self, format, dst, y);
                    continue;
                }
                for x in 0..desc.width {
                    packed.clear();
                    for s in 0..self.samples() {
                        let fb = self.sample(s).expect("s < samples");
                        let off = fb.color_offset(x, y);
                        packed.push(pixel::load(format, &fb.color_bytes()[off..]));
                    }
                    let v = resolve_value(format, &packed);
                    let at = x as usize * bpp;
                    pixel::store(format, &mut dst[at..at + bpp], v);
                }
            }
            // Depth and stencil: sample 0's.
            if let (Some(from), Some(to)) = (self.depth_buffer(), t.depth_mut()) {
                match (from, to) {
                    (DepthBuffer::D16(a), DepthTarget::D16(b)) => b.copy_from_slice(a),
                    (DepthBuffer::D24(a), DepthTarget::D24(b))
                    | (DepthBuffer::D32(a), DepthTarget::D32(b))
                    | (DepthBuffer::D32F(a), DepthTarget::D32F(b)) => b.copy_from_slice(a),
                    _ => return Err(GlError::InvalidOperation),
                }
            }
            if let (Some(from), Some(to)) = (self.stencil_buffer(), t.stencil_mut()) {
                to.copy_from_slice(from);
            }
        }
        Ok(out)
    }
}

impl Framebuffer {
    /// The colour of `r` resolved as [`Framebuffer::resolve`] resolves it,
    /// written straight into the same rectangle of `to` (single-sampled, of
    /// the same colour format): a same-size `glBlitFramebuffer` resolve
    /// without the intermediate framebuffer (MuJoCo's, every frame).
    /// `false`, and nothing written, unless both have 8-bit channels, `self`
    /// 4 samples and `r` lies inside both.
    pub(crate) fn resolve_color_into(&self, to: &mut Framebuffer, r: crate::framebuffer::Rect) -> bool {
        let format = self.desc().color;
        let eight_bits = matches!(format, ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8);
        let inside = |fb: &Framebuffer| r.x1 <= fb.width() && r.y1 <= fb.height();
        if !eight_bits
            || self.samples() != 4
            || to.samples() != 1
            || to.color_format() != format
            || r.is_empty()
            || !inside(self)
            || !inside(to)
        {
            return false;
        }
        let bpp = format.bytes_per_pixel();
        let bytes = (r.x1 - r.x0) as usize * bpp;
        let mut t = to.target();
        for y in r.y0..r.y1 {
            let row = |s: u32| {
                let fb = self.sample(s).expect("s < samples");
                &fb.color_bytes()[fb.color_offset(r.x0, y)..][..bytes]
            };
            let o = t.color_offset(r.x0, y);
            resolve_row_4x8(&mut t.color_mut()[o..o + bytes], [row(0), row(1), row(2), row(3)]);
        }
        true
    }
}

/// Depth and stencil of samples 1.. inside a rectangle, as
/// [`Framebuffer::tests_from_sample0`] found them.
pub(crate) struct SavedTests {
    rect: crate::framebuffer::Rect,
    depth: Vec<Vec<u32>>,
    stencil: Vec<Vec<u8>>,
}

fn cells(r: crate::framebuffer::Rect) -> impl Iterator<Item = (u32, u32)> {
    (r.y0..r.y1).flat_map(move |y| (r.x0..r.x1).map(move |x| (x, y)))
}

impl Framebuffer {
    /// For a pixel rectangle or bitmap drawn with depth or stencil test into
    /// a multisampled framebuffer: llvmpipe draws them with its rasterizer's
    /// `multisample` off (`st_cb_bitmap.c`, `st_cb_drawpixels.c` memset their
    /// rasterizer state), so depth and stencil are tested and written in
    /// sample 0 only and the colour written to every sample with sample 0's
    /// mask (`docs/llvmpipe-facts.md`, `GL_MULTISAMPLE` off). Samples 1..
    /// get sample 0's depth and stencil inside `r` (their tests then pass
    /// where sample 0's do); [`Framebuffer::restore_tests`] puts theirs back
    /// after the draw is rasterized.
    pub(crate) fn tests_from_sample0(&mut self, r: crate::framebuffer::Rect) -> SavedTests {
        let zero: Vec<(Option<u32>, Option<u8>)> = cells(r)
            .map(|(x, y)| (self.depth_at(x, y), self.stencil_at(x, y)))
            .collect();
        let mut saved = SavedTests {
            rect: r,
            depth: Vec::new(),
            stencil: Vec::new(),
        };
        for fb in &mut self.samples {
            let (mut d, mut s) = (Vec::new(), Vec::new());
            let mut t = fb.target();
            for ((x, y), (z0, s0)) in cells(r).zip(&zero) {
                let i = t.index(x, y);
                match t.depth_mut() {
                    Some(DepthTarget::D16(v)) => {
                        d.push(u32::from(v[i]));
                        if let Some(z) = z0 {
                            v[i] = *z as u16;
                        }
                    }
                    Some(DepthTarget::D24(v) | DepthTarget::D32(v) | DepthTarget::D32F(v)) => {
                        d.push(v[i]);
                        if let Some(z) = z0 {
                            v[i] = *z;
                        }
                    }
                    None => {}
                }
                if let Some(st) = t.stencil_mut() {
                    s.push(st[i]);
                    if let Some(v) = s0 {
                        st[i] = *v;
                    }
                }
            }
            saved.depth.push(d);
            saved.stencil.push(s);
        }
        saved
    }

    /// Puts back what [`Framebuffer::tests_from_sample0`] saved.
    pub(crate) fn restore_tests(&mut self, saved: SavedTests) {
        let r = saved.rect;
        for ((fb, d), s) in self.samples.iter_mut().zip(saved.depth).zip(saved.stencil) {
            let mut t = fb.target();
            for (k, (x, y)) in cells(r).enumerate() {
                let i = t.index(x, y);
                match t.depth_mut() {
                    Some(DepthTarget::D16(v)) => v[i] = d[k] as u16,
                    Some(DepthTarget::D24(v) | DepthTarget::D32(v) | DepthTarget::D32F(v)) => v[i] = d[k],
                    None => {}
                }
                if let (Some(st), Some(&sv)) = (t.stencil_mut(), s.get(k)) {
                    st[i] = sv;
                }
            }
        }
    }
}

/// `c · f32(1/255)` for each byte `c` (`lp_build_unsigned_norm_to_float`),
/// made once at compile time: [`resolve_row_4x8`] made it at each row,
/// ~800 instructions a row.
static UNORM8: [f32; 256] = {
    let to_float = (1.0f64 / 255.0) as f32;
    let mut t = [0.0f32; 256];
    let mut c = 0;
    while c < 256 {
        t[c] = c as f32 * to_float;
        c += 1;
    }
    t
};

/// [`resolve_value`] of four samples of an 8-bit-channel format, byte by
/// byte over rows (a 640×480 resolve took 77 ms a pixel at a time): each
/// byte `c` as `c · f32(1/255)` from a table, summed in sample order, times
/// 0.25, `rint(v · 255)`. Four equal bytes give that byte: the sum of four
/// equal values is within a few ulps of `4v`, far from a half.
fn resolve_row_4x8(dst: &mut [u8], src: [&[u8]; 4]) {
    let unorm = &UNORM8;
    let byte = |p: u8, q: u8, r: u8, s: u8| {
        if p == q && q == r && r == s {
            p
        } else {
            let sum = ((unorm[p as usize] + unorm[q as usize]) + unorm[r as usize]) + unorm[s as usize];
            rint_nonnegative((sum * 0.25).clamp(0.0, 1.0) * 255.0) as u8
        }
    };
    let [a, b, c, d] = src;
    // Each byte depends on its own four samples only, so 8 bytes whose
    // samples all agree (a polygon's inside) copy at once: the resolve of
    // a 320×240 MuJoCo frame was ~90 instructions a pixel byte by byte.
    let n = dst.len().min(a.len()).min(b.len()).min(c.len()).min(d.len());
    let whole = n / 8 * 8;
    let word = |v: &[u8]| u64::from_ne_bytes(v.try_into().unwrap_or([0; 8]));
    let runs = dst[..whole]
        .chunks_exact_mut(8)
        .zip(a[..whole].chunks_exact(8).zip(b[..whole].chunks_exact(8)))
        .zip(c[..whole].chunks_exact(8).zip(d[..whole].chunks_exact(8)));
    for ((o, (pa, pb)), (pc, pd)) in runs {
        let w = word(pa);
        if w == word(pb) && w == word(pc) && w == word(pd) {
            o.copy_from_slice(pa);
        } else {
            for (k, o) in o.iter_mut().enumerate() {
                *o = byte(pa[k], pb[k], pc[k], pd[k]);
            }
        }
    }
    for (k, o) in dst.iter_mut().enumerate().take(n).skip(whole) {
        *o = byte(a[k], b[k], c[k], d[k]);
    }
}

/// Row `y` of `fb` resolved into `dst`, of deep format `format`, as
/// [`Framebuffer::resolve`] says: the samples' float values
/// (`deep::to_float`: unorm16 times `1/65535`, floats as stored; bytes
/// times `1/255`) summed in sample order, the first taken as it is
/// (`util_make_fs_msaa_resolve`: a `MOV` then `ADD`s), times `1/samples`,
/// stored as a fragment colour of `format` (`deep::from_float`: unorm16
/// rounded, halves truncated).
fn resolve_row_deep(fb: &Framebuffer, format: ColorFormat, dst: &mut [u8], y: u32) {
    let from = fb.desc().color;
    let bpp = format.bytes_per_pixel();
    let scale = 1.0 / fb.samples() as f32;
    for x in 0..fb.width() {
        let mut sum = [0.0f32; 4];
        for s in 0..fb.samples() {
            let sample = fb.sample(s).expect("s < samples");
            let off = sample.color_offset(x, y);
            let bytes = &sample.color_bytes()[off..];
            let c = if from.is_deep() {
                deep::to_float(from, deep::load(from, bytes))
            } else {
                pixel::unpack(from, pixel::load(from, bytes)).map(|v| f32::from(v) * (1.0 / 255.0))
            };
            for k in 0..4 {
                sum[k] = if s == 0 { c[k] } else { sum[k] + c[k] };
            }
        }
        let at = x as usize * bpp;
        let v = deep::from_float(format, sum.map(|v| v * scale));
        for (k, v) in v.into_iter().enumerate() {
            deep::store_channel(format, &mut dst[at..at + bpp], k, v);
        }
    }
}

/// The resolved packed colour of the packed sample colours `samples` of
/// `format` ([`Framebuffer::resolve`]).
pub fn resolve_value(format: ColorFormat, samples: &[u32]) -> u32 {
    if samples.len() == 1 {
        return samples[0];
    }
    let scale = 1.0 / samples.len() as f32;
    // Each channel's bits (shift, width) in the packed value.
    let channels: &[(u32, u32)] = match format {
        ColorFormat::Rgb565 => &[(11, 5), (5, 6), (0, 5)],
        ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8 => &[(0, 8), (8, 8), (16, 8), (24, 8)],
        // Deep formats do not fit a packed u32 (`resolve_row_deep`).
        ColorFormat::Rgba16
        | ColorFormat::Rgbx16
        | ColorFormat::Rgba16F
        | ColorFormat::Rgbx16F
        | ColorFormat::Rgba32F
        | ColorFormat::Rgbx32F => return samples[0],
    };
    let mut out = 0u32;
    for &(shift, width) in channels {
        let max = (1u32 << width) - 1;
        let to_float = (1.0f64 / f64::from(max)) as f32;
        let mut sum = 0.0f32;
        for &v in samples {
            sum += ((v >> shift) & max) as f32 * to_float;
        }
        let avg = (sum * scale).clamp(0.0, 1.0);
        let c = rint_nonnegative(avg * max as f32) as u32;
        out |= c.min(max) << shift;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_offsets_are_exact_in_fixed_point() {
        let fixed: Vec<_> = (0..4).map(|s| SampleAt::of_4x(s).fixed).collect();
        assert_eq!(fixed, [(-32, -96), (96, -32), (-96, 32), (32, 96)]);
        assert_eq!(SampleAt::of_4x(0).plane, (-0.125, 0.375));
    }

    #[test]
    fn renderbuffers_get_mesas_sample_counts() {
        let got: Vec<_> = (-1..=5).map(renderbuffer_samples).collect();
        use GlError::*;
        assert_eq!(
            got,
            [
                Err(InvalidValue),
                Ok(1),
                Ok(4),
                Ok(4),
                Ok(4),
                Ok(4),
                Err(InvalidOperation)
            ]
        );
    }

    #[test]
    fn coverage_masks_as_mesa_makes_them() {
        assert_eq!(sample_coverage_mask(1.0, false, 4), 0xf);
        assert_eq!(sample_coverage_mask(0.5, false, 4), 0x3);
        assert_eq!(sample_coverage_mask(0.74, false, 4), 0x3);
        assert_eq!(sample_coverage_mask(0.75, false, 4), 0x7);
        assert_eq!(sample_coverage_mask(0.0, false, 4), 0);
        assert_eq!(sample_coverage_mask(0.5, true, 4) & 0xf, 0xc);
    }

    #[test]
    fn resolving_averages_in_f32_and_rounds_to_even() {
        let rgba = |c: [u8; 4]| u32::from_le_bytes(c);
        // Equal samples stay.
        assert_eq!(
            resolve_value(ColorFormat::Rgba8, &[rgba([7, 8, 9, 10]); 4]),
            rgba([7, 8, 9, 10])
        );
        // 255 in one of four: 63.75 -> 64; in two: 127.5, a tie (in f32
        // exactly) -> 128, even.
        let one = resolve_value(ColorFormat::Rgba8, &[rgba([255, 0, 0, 255]), 0, 0, 0]);
        assert_eq!(one.to_le_bytes(), [64, 0, 0, 64]);
        let half = resolve_value(ColorFormat::Rgba8, &[rgba([255, 0, 0, 0]), rgba([255, 0, 0, 0]), 0, 0]);
        assert_eq!(half.to_le_bytes()[0], 128);
        // 2 in one sample of four: 0.5 -> 0 (ties to even).
        let small = resolve_value(ColorFormat::Rgba8, &[rgba([2, 0, 0, 0]), 0, 0, 0]);
        assert_eq!(small.to_le_bytes()[0], 0);
    }

    #[test]
    fn resolving_rows_equals_resolving_pixels() {
        let mut seed = 0x9e37_79b9u32;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        // Random bytes, and bytes from a few values (equal samples often).
        for round in 0..400 {
            let few = [0u8, 1, 2, 127, 128, 254, 255, 77];
            let mut byte = || match round % 2 {
                0 => next() as u8,
                _ => few[next() as usize % few.len()],
            };
            let src: Vec<Vec<u8>> = (0..4).map(|_| (0..64).map(|_| byte()).collect()).collect();
            let mut dst = vec![0u8; 64];
            resolve_row_4x8(&mut dst, [&src[0], &src[1], &src[2], &src[3]]);
            for px in 0..16 {
                let packed: Vec<u32> = (0..4)
                    .map(|s| u32::from_le_bytes(src[s][4 * px..4 * px + 4].try_into().unwrap()))
                    .collect();
                let want = resolve_value(ColorFormat::Rgba8, &packed).to_le_bytes();
                assert_eq!(dst[4 * px..4 * px + 4], want, "{packed:x?}");
            }
        }
    }

    #[test]
    fn a_multisampled_framebuffer_resolves_its_samples() {
        let desc = FramebufferDesc::rgba8_d24s8(3, 2);
        assert_eq!(Framebuffer::new_multisample(desc, 2).err(), Some(GlError::InvalidValue));
        let fb = Framebuffer::new_multisample(desc, 4).unwrap();
        assert_eq!(fb.samples(), 4);
        assert!(fb.sample(3).is_some() && fb.sample(4).is_none());
        let r = fb.resolve().unwrap();
        assert_eq!(r.samples(), 1);
        assert_eq!(r.pixel(2, 1), Some([0, 0, 0, 0]));
        assert_eq!(r.depth_at(2, 1), Some(0xff_ffff));
    }

    /// llvmpipe's coverage of sample `s` of pixel `(i, j)` in a framebuffer
    /// object, from its own set-up (`lp_setup_tri.c`: positions snapped
    /// with no pixel offset when multisampling, `rint(v · 256)`; the planes
    /// `c = dcdx·x_i − dcdy·y_i`, plus one on left edges and, with the
    /// top-left rule of a y-up framebuffer object, on horizontal edges with
    /// `dcdy > 0`; `lp_rast_tri_tmp.h`: a sample is in when
    /// `c + dcdy·sy − dcdx·sx − 1 >= 0` at its fixed-point position).
    fn llvmpipe_sample(v: [(i64, i64); 3], i: i64, j: i64, s: usize) -> bool {
        let (mut x, mut y) = (v.map(|p| p.0), v.map(|p| p.1));
        let area = (x[0] - x[1]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[0] - y[1]);
        if area == 0 {
            return false;
        }
        if area < 0 {
            x.swap(0, 1);
            y.swap(0, 1);
        }
        let (fx, fy) = SAMPLE_POSITIONS_4X[s];
        let (px, py) = (i * 256 + (fx * 256.0) as i64, j * 256 + (fy * 256.0) as i64);
        (0..3).all(|k| {
            let n = (k + 1) % 3;
            let (dcdx, dcdy) = (y[k] - y[n], x[k] - x[n]);
            let mut c = dcdx * x[k] - dcdy * y[k];
            if dcdx < 0 || (dcdx == 0 && dcdy > 0) {
                c += 1;
            }
            // (`c − 1 >= 0` in llvmpipe's words.)
            c + dcdy * py - dcdx * px > 0
        })
    }

    use crate::framebuffer::Rect;
    use crate::raster::{row_coverage, tile_coverage, Edges, TileMask};
    use proptest::prelude::*;

    const W: u32 = 40;
    const H: u32 = 36;

    /// Sample `s`'s coverage of the framebuffer as softgl finds it for a
    /// triangle of the fixed-point GL positions `v` (multiples of 1/256, so
    /// that no snap rounds): the snapped points `Binner::triangle_at` moves,
    /// covered by the block rasterizer and by the row rasterizer (which
    /// must agree), and by the small-box set-up a scene records.
    fn softgl_sample(v: [(i64, i64); 3], s: usize) -> TileMask {
        let to = |(x, y): (i64, i64)| {
            let mut r = crate::raster::RasterVertex {
                x: x as f32 / 256.0,
                y: y as f32 / 256.0,
                y_down: 0.0,
                z: 0.5,
                inv_w: 1.0,
                v: [0.0; crate::geometry::varying::MAX_VARYINGS],
            };
            r.y_down = H as f32 - r.y;
            r
        };
        let rv = v.map(to);
        let p = Edges::window_points([&rv[0], &rv[1], &rv[2]], H);
        let at = SampleAt::of_4x(s);
        let moved = p.map(|(x, y)| (x - at.fixed.0, y - at.fixed.1));
        let tile = Rect {
            x0: 0,
            y0: 0,
            x1: W,
            y1: H,
        };
        let rows = row_coverage(moved, tile, tile);
        let blocks = Edges::new(moved).map_or(TileMask::empty(0, 0), |e| tile_coverage(&e, tile, tile));
        assert_eq!(rows, blocks, "sample {s}: rows and blocks");
        let mut prepared = TileMask::empty(0, 0);
        if let Some(prep) = crate::raster::triangle::Prepared::new(moved, tile) {
            let mut sink = |span: &softgl_jit::FragmentSpan| {
                for b in 0..span.len {
                    if span.mask >> b & 1 == 1 {
                        prepared.rows[span.y as usize] |= 1 << (span.x + b);
                    }
                }
            };
            prep.cover(tile, H, &mut sink, |_| None);
        }
        assert_eq!(rows, prepared, "sample {s}: rows and the scene's set-up");
        rows
    }

    fn check(v: [(i64, i64); 3]) -> Result<(), TestCaseError> {
        for s in 0..4 {
            let got = softgl_sample(v, s);
            for j in 0..H {
                for i in 0..W {
                    let want = llvmpipe_sample(v, i64::from(i), i64::from(j), s);
                    prop_assert_eq!(got.covers(i, j), want, "sample {} of ({}, {}) of {:?}", s, i, j, v);
                }
            }
        }
        Ok(())
    }

    #[test]
    fn edges_through_sample_positions() {
        // Edges on the samples' rows and columns (exact ties), both windings.
        for v in [
            [(1000, 2080), (8000, 2080), (4000, 6000)],
            [(1000, 2080), (4000, 6000), (8000, 2080)],
            [(2144, 1000), (2144, 7000), (6000, 4000)],
            [(2144, 1000), (6000, 4000), (2144, 7000)],
            [(512, 512), (5120, 512), (512, 5120)],
            [(5120, 5120), (512, 5120), (5120, 512)],
        ] {
            check(v).unwrap();
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]
        /// Every sample of every pixel as llvmpipe decides it: vertices on
        /// the 1/256 grid (sample positions and their rows and columns are
        /// hit often), and on a coarse 1/8 grid (edges through them more).
        #[test]
        fn four_samples_as_llvmpipe_covers_them(
            v in prop::array::uniform3((-512i64..(W as i64 + 2) * 256, -512i64..(H as i64 + 2) * 256)),
            coarse in prop::array::uniform3((-4i64..(W as i64 + 2) * 8, -4i64..(H as i64 + 2) * 8)),
        ) {
            check(v)?;
            check(coarse.map(|(x, y)| (x * 32, y * 32)))?;
        }
    }
}
