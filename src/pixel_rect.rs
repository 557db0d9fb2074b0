//! Bitmaps and pixel rectangles drawn at the raster position (GL 1.5 §3.6,
//! §3.7): their fragments run the draw's fragment specialist as a
//! primitive's do (scissor, alpha, stencil, depth, blend, logic op, masks),
//! recorded in the deferred scene in order with the primitives
//! (`raster/scene.rs`), rasterized per tile.
//!
//! What llvmpipe runs for them (Mesa's `state_tracker/st_cb_bitmap.c`): a
//! bitmap is a screen-aligned quad at `floor(raster + 1e-4 - orig)`, whose
//! fragments are the bitmap's set bits, at the raster position's depth,
//! with the raster colour as a constant: the current fragment shader runs
//! on them (texture environment, colour sum, fog), `docs/llvmpipe-facts.md`.

use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::framebuffer::Rect;
use crate::geometry::varying::{Varyings, MAX_VARYINGS};
use crate::pixel_shade::PixelShade;
use crate::raster::scene::DrawState;
use crate::raster::{RasterParams, RasterVertex};
use crate::texture::PixelStore;
use crate::Backend;
use std::sync::Arc;

/// A `glBitmap` image, unpacked: bit `x` of row `y` (bottom-up) says whether
/// the pixel at `(x, y)` from the image's origin makes a fragment.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BitmapImage {
    width: u32,
    height: u32,
    /// 64-bit words a row.
    words: u32,
    bits: Arc<[u64]>,
}

impl BitmapImage {
    /// An empty (`0×0`) bitmap.
    pub fn empty() -> BitmapImage {
        BitmapImage {
            width: 0,
            height: 0,
            words: 0,
            bits: Arc::from(Vec::new()),
        }
    }

    /// A `width`×`height` bitmap with no bit set (a null image: GL draws
    /// nothing, and moves the raster position). Negative sizes count as 0.
    pub fn empty_sized(width: i32, height: i32) -> BitmapImage {
        let (w, h) = (width.max(0) as u32, height.max(0) as u32);
        let words = w.div_ceil(64);
        BitmapImage {
            width: w,
            height: h,
            words,
            bits: Arc::from(vec![0u64; words as usize * h as usize]),
        }
    }

    /// Bytes a `width`×`height` bitmap reads from client memory under
    /// `store` (rows padded to the alignment, skipped rows and pixels
    /// counted); `None` when negative.
    pub fn client_bytes(width: i32, height: i32, store: &PixelStore) -> Option<usize> {
        if width < 0 || height < 0 {
            return None;
        }
        if width == 0 || height == 0 {
            return Some(0);
        }
        let (stride, skip_pixels, skip_rows) = Self::layout(width, store);
        let last_row = (skip_rows + height as usize - 1) * stride;
        Some(last_row + (skip_pixels + width as usize).div_ceil(8))
    }

    /// Bytes a row, bits skipped at the start of a row, rows skipped.
    fn layout(width: i32, store: &PixelStore) -> (usize, usize, usize) {
        let row_length = if store.row_length > 0 { store.row_length } else { width } as usize;
        let align = store.alignment.max(1) as usize;
        let stride = row_length.div_ceil(8).div_ceil(align) * align;
        (
            stride,
            store.skip_pixels.max(0) as usize,
            store.skip_rows.max(0) as usize,
        )
    }

    /// Unpacks a `width`×`height` bitmap from `data` as GL reads client
    /// memory under `store` (`GL_UNPACK_LSB_FIRST`, alignment, row length,
    /// skipped rows and pixels): negative sizes are `InvalidValue`, data
    /// shorter than [`Self::client_bytes`] `InvalidOperation`.
    pub fn unpack(width: i32, height: i32, data: &[u8], store: &PixelStore) -> GlResult<BitmapImage> {
        let need = Self::client_bytes(width, height, store).ok_or(GlError::InvalidValue)?;
        if data.len() < need {
            return Err(GlError::InvalidOperation);
        }
        let (w, h) = (width as u32, height as u32);
        let words = w.div_ceil(64);
        let mut bits = vec![0u64; words as usize * h as usize];
        let (stride, skip_pixels, skip_rows) = Self::layout(width, store);
        for y in 0..h as usize {
            let row = &data[(skip_rows + y) * stride..];
            for x in 0..w as usize {
                let b = skip_pixels + x;
                let byte = row[b / 8];
                let bit = if store.lsb_first { b % 8 } else { 7 - b % 8 };
                if byte >> bit & 1 != 0 {
                    bits[y * words as usize + x / 64] |= 1 << (x % 64);
                }
            }
        }
        Ok(BitmapImage {
            width: w,
            height: h,
            words,
            bits: Arc::from(bits),
        })
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    /// A `width`×`height` bitmap of the rows `bits`, `width.div_ceil(64)`
    /// words each (bits past the width ignored).
    pub fn from_words(width: u32, height: u32, bits: Vec<u64>) -> BitmapImage {
        let words = width.div_ceil(64);
        debug_assert_eq!(bits.len(), words as usize * height as usize);
        BitmapImage {
            width,
            height,
            words,
            bits: Arc::from(bits),
        }
    }

    /// ORs the bits into `dst` (rows of `words` words) at column `px`, row `py`.
    pub fn or_into(&self, dst: &mut [u64], words: u32, px: u32, py: u32) {
        for y in 0..self.height {
            let row = &mut dst[((py + y) * words) as usize..][..words as usize];
            let mut x = 0;
            while x < self.width {
                let bits = self.row_bits(y, x);
                let at = px + x;
                let (w, b) = ((at / 64) as usize, at % 64);
                if let Some(r) = row.get_mut(w) {
                    *r |= bits << b;
                }
                if b != 0 {
                    if let Some(r) = row.get_mut(w + 1) {
                        *r |= bits >> (64 - b);
                    }
                }
                x += 64;
            }
        }
    }

    /// Bytes of its bits.
    pub fn bytes(&self) -> usize {
        self.bits.len() * 8
    }

    pub fn height(&self) -> u32 {
        self.height
    }

    /// Whether the pixel at `(x, y)` of the image makes a fragment.
    pub fn get(&self, x: u32, y: u32) -> bool {
        x < self.width && y < self.height && self.row_bits(y, x) & 1 != 0
    }

    /// The 64 bits of row `y` from column `x` on (zeros past the width).
    pub fn row_bits(&self, y: u32, x: u32) -> u64 {
        let row = &self.bits[(y * self.words) as usize..][..self.words as usize];
        let (w, b) = ((x / 64) as usize, x % 64);
        let lo = row.get(w).copied().unwrap_or(0) >> b;
        let hi = match b {
            0 => 0,
            _ => row.get(w + 1).copied().unwrap_or(0) << (64 - b),
        };
        let bits = lo | hi;
        let left = self.width.saturating_sub(x);
        if left >= 64 {
            bits
        } else {
            bits & ((1u64 << left) - 1)
        }
    }
}

/// Mesa's bitmap cache (`st_cb_bitmap.c`, `accum_bitmap`): bitmaps drawn
/// one after the other with the same raster colour and depth, whose boxes
/// fit in a 512×32 window placed at the first (vertically centred on it),
/// are merged into one bitmap (their bits ORed) and drawn as one quad:
/// where two overlap, the pixel makes one fragment, not two (it is blended
/// and counted by the stencil once). softgl merges them likewise while the
/// fragment state stays the same; Mesa also merges across state changes
/// (its cache is drawn with the state current when a draw, clear, flush,
/// read or scissor change empties it), which softgl does not copy.
pub const CACHE_WIDTH: u32 = 512;
/// See [`CACHE_WIDTH`].
pub const CACHE_HEIGHT: u32 = 32;

/// A bitmap placed in the window: its image and the window position of its
/// lower-left pixel.
#[derive(Clone, Debug)]
pub struct PlacedBitmap {
    pub image: BitmapImage,
    pub x: i64,
    pub y: i64,
}

impl PlacedBitmap {
    /// The window pixels it may cover inside `bounds`.
    pub fn rect(&self, bounds: Rect) -> Option<Rect> {
        let clamp = |v: i64, lo: u32, hi: u32| v.clamp(i64::from(lo), i64::from(hi)) as u32;
        let r = Rect {
            x0: clamp(self.x, bounds.x0, bounds.x1),
            y0: clamp(self.y, bounds.y0, bounds.y1),
            x1: clamp(self.x.saturating_add(i64::from(self.image.width)), bounds.x0, bounds.x1),
            y1: clamp(
                self.y.saturating_add(i64::from(self.image.height)),
                bounds.y0,
                bounds.y1,
            ),
        };
        (!r.is_empty()).then_some(r)
    }
}

impl Context {
    /// What the fragments of a bitmap or pixel rectangle run with, as a
    /// draw made now would (its key, uniforms, specialist and textures),
    /// the raster parameters (the whole framebuffer, llvmpipe's viewport for
    /// them) and the raster position as a vertex carrying its colours,
    /// fog distance and texture coordinates in the draw's layout.
    ///
    /// For pixel rectangles also the shading stage their colours go through
    /// before they are recorded ([`PixelShade`]), when one is on.
    fn raster_draw(&mut self, pixels: bool) -> GlResult<(DrawState, RasterParams, RasterVertex, Option<PixelShade>)> {
        let textures = (&*self.tex_units, &*self.textures);
        let (mut key, mut layout, textures) =
            crate::context::plan(&self.state, &self.fb, self.ordered_dither, textures);
        let r = self.raster;
        let mut shade = None;
        if pixels {
            let at = (&r.tex_coords, r.secondary, r.distance);
            shade = PixelShade::new(key.shade.as_ref(), &textures, at, self.state.fog.uniforms());
            // Pixel rectangles bring their colours and depths in the spans;
            // only multisampling's alpha stages stay, as for bitmaps:
            // llvmpipe draws them with multisampling off in its rasterizer
            // state, so alpha to coverage keeps the fragment, in every
            // sample, when its alpha is above 0.5 (`lp_build_alpha_to_coverage`).
            key.shade = key
                .shade
                .map(|s| s.coverage)
                .filter(softgl_jit::AlphaCoverage::is_on)
                .map(|c| softgl_jit::ShadeKey {
                    coverage: softgl_jit::AlphaCoverage {
                        quarters: c.quarters.map(|_| 2),
                        ..c
                    },
                    ..softgl_jit::ShadeKey::default()
                });
        } else {
            if layout.color {
                layout.uniform_colors = true;
                if let Some(shade) = key.shade.as_mut() {
                    shade.flat = true;
                }
            }
            // Bitmaps are drawn with multisampling off in llvmpipe's
            // rasterizer state: alpha to coverage keeps the fragment, in
            // every sample, when alpha is above 0.5 (`lp_build_alpha_to_coverage`).
            if let Some(shade) = key.shade.as_mut().filter(|s| s.coverage.quarters.is_some()) {
                shade.coverage.quarters = Some(2);
            }
        }
        let fb = &self.fb;
        if key.validate().is_err()
            || (key.color_format, key.depth_format, key.stencil_buffer)
                != (fb.color_format(), fb.depth_format(), fb.has_stencil())
        {
            return self.record(Err(GlError::InvalidOperation));
        }
        let mut v: Varyings = [0.0; MAX_VARYINGS];
        let mut put = |o: Option<usize>, c: &[f32]| {
            if let Some(o) = o {
                v[o..o + c.len()].copy_from_slice(c);
            }
        };
        let clamp = |c: glam::Vec4| c.to_array().map(|c| if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) });
        put(layout.color(), &clamp(r.color));
        put(layout.back_color(), &clamp(r.color));
        put(layout.secondary(), &clamp(r.secondary));
        put(layout.back_secondary(), &clamp(r.secondary));
        // GL: the raster distance. (llvmpipe's pass-through vertex shader for
        // these quads writes no fog coordinate: its fragments read 0,
        // `docs/llvmpipe-facts.md` §26.)
        put(layout.fog(), &[r.distance]);
        for (u, o) in layout.tex_units() {
            put(Some(o), &r.tex_coords[u].to_array());
        }
        let height = fb.height();
        let vertex = RasterVertex {
            x: r.window[0],
            y: r.window[1],
            y_down: height as f32 - r.window[1],
            z: f64::from(r.window[2]),
            inv_w: 1.0,
            v,
        };
        let params = RasterParams {
            bounds: fb.bounds(),
            depth: fb.depth_format().filter(|_| key.depth.is_some()),
            height,
            layout,
            offset: None,
        };
        // An active occlusion query counts these fragments too.
        let samples = self.queries().counter();
        key.count = samples.is_some();
        let specialist = match self.backend {
            Backend::Jit => self.specialists.get(&key).cloned(),
            Backend::Interpreter => None,
        };
        let uniforms = self.state.fragment_uniforms();
        let state = DrawState {
            key,
            uniforms,
            specialist,
            textures: textures.share(),
            samples,
            // Polygon stipple applies to polygons only.
            polygon_stipple: None,
            shades_samples: false,
        };
        Ok((state, params, vertex, shade))
    }

    /// `glBitmap`: draws `image` with its origin `orig` at the raster
    /// position, then moves the raster position by `moves`. Nothing at all
    /// (no move either) when the raster position is invalid.
    pub fn bitmap(&mut self, image: &BitmapImage, orig: [f32; 2], moves: [f32; 2]) -> GlResult {
        self.outside()?;
        self.acquire_deferred();
        if !self.raster.valid {
            return Ok(());
        }
        let r = self.raster;
        let drawn = !self.render_mode.raster_primitive(crate::select::token::BITMAP, &r);
        if drawn && image.width > 0 && image.height > 0 {
            const EPSILON: f32 = 0.0001;
            let [rx, ry, ..] = self.raster.window;
            let x = (rx + EPSILON - orig[0]).floor();
            let y = (ry + EPSILON - orig[1]).floor();
            if x.is_finite() && y.is_finite() {
                let placed = PlacedBitmap {
                    image: image.clone(),
                    x: x as i64,
                    y: y as i64,
                };
                let (state, params, vertex, _) = self.raster_draw(false)?;
                let colour = self.raster.color.to_array();
                let saved = self.one_sample_tests(placed.rect(params.bounds));
                for (scene, fb) in self.lane_scenes() {
                    scene.bitmap(state.clone(), &params, vertex, placed.clone(), colour, fb);
                }
                self.scene.bitmap(state, &params, vertex, placed, colour, &self.fb);
                self.end_one_sample_tests(saved);
            }
        }
        self.raster.window[0] += moves[0];
        self.raster.window[1] += moves[1];
        Ok(())
    }
}

/// What a pixel rectangle writes, per source pixel.
#[derive(Clone, Debug)]
pub enum RectPixels {
    /// Colours (`glDrawPixels` of a colour or index format, `GL_COLOR`
    /// copies); the fragments' depth is `z` (buffer units).
    Color { rgba: Arc<[[u8; 4]]>, z: u32 },
    /// Depths in buffer units; the fragments' colour is `rgba`.
    Depth { z: Arc<[u32]>, rgba: [u8; 4] },
    /// Stencil values, written through `write_mask` inside `scissor` (when
    /// on) with no other test, as llvmpipe writes them (`st_cb_drawpixels.c`:
    /// stencil `ALWAYS`/`REPLACE`, depth test and colour writes off).
    ///
    /// `z`: `GL_DEPTH_STENCIL` rectangles also write these depths (buffer
    /// units) as they are, when the depth mask is on: llvmpipe's depth test
    /// `ALWAYS` for them (`st_cb_drawpixels.c`, `write_depth` with `write_stencil`).
    Stencil {
        s: Arc<[u8]>,
        write_mask: u8,
        scissor: Option<Rect>,
        z: Option<Arc<[u32]>>,
    },
}

/// A pixel rectangle placed in the window: `width`×`height` source pixels
/// from window `(x, y)`, each `zoom` pixels wide and high (negative: to the
/// left, down). A window pixel is covered when its centre is inside the
/// zoomed rectangle, left and bottom edges included (llvmpipe's quad with
/// `bottom_edge_rule`), and takes the source pixel under its centre.
#[derive(Clone, Debug)]
pub struct PlacedImage {
    pub pixels: RectPixels,
    pub width: u32,
    pub height: u32,
    pub x: f32,
    pub y: f32,
    pub zoom: [f32; 2],
}

impl PlacedImage {
    /// Window pixels `lo..hi` whose centres are in `[a, a + n·zoom)` (or
    /// `[a + n·zoom, a)`), as i64.
    fn span(a: f32, n: u32, zoom: f32) -> Option<(i64, i64)> {
        let b = f64::from(a) + f64::from(n) * f64::from(zoom);
        let (lo, hi) = (f64::from(a).min(b), f64::from(a).max(b));
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        let lo = (lo - 0.5).ceil().clamp(-1e12, 1e12) as i64;
        let hi = (hi - 0.5).ceil().clamp(-1e12, 1e12) as i64;
        (lo < hi).then_some((lo, hi))
    }

    /// The window pixels it covers inside `bounds`.
    pub fn rect(&self, bounds: Rect) -> Option<Rect> {
        let (x0, x1) = Self::span(self.x, self.width, self.zoom[0])?;
        let (y0, y1) = Self::span(self.y, self.height, self.zoom[1])?;
        let c = |v: i64, lo: u32, hi: u32| v.clamp(i64::from(lo), i64::from(hi)) as u32;
        let r = Rect {
            x0: c(x0, bounds.x0, bounds.x1),
            y0: c(y0, bounds.y0, bounds.y1),
            x1: c(x1, bounds.x0, bounds.x1),
            y1: c(y1, bounds.y0, bounds.y1),
        };
        (!r.is_empty()).then_some(r)
    }

    /// The source column (or row) under window pixel `p`'s centre (GL's
    /// `floor((centre - origin) / zoom)`, exact). llvmpipe interpolates a
    /// texture coordinate over its quad's two triangles, each rounding a
    /// centre exactly on a boundary between source pixels its own way: at
    /// such ties (fractional zooms) it may take the neighbour.
    fn source(p: u32, a: f32, zoom: f32, n: u32) -> u32 {
        let i = ((f64::from(p) + 0.5 - f64::from(a)) / f64::from(zoom)).floor();
        i.clamp(0.0, f64::from(n.saturating_sub(1))) as u32
    }

    /// The source pixel index under window pixel `(px, py)`.
    pub fn at(&self, px: u32, py: u32) -> usize {
        let i = Self::source(px, self.x, self.zoom[0], self.width);
        let j = Self::source(py, self.y, self.zoom[1], self.height);
        j as usize * self.width as usize + i as usize
    }

    /// Bytes it holds.
    pub fn bytes(&self) -> usize {
        let n = self.width as usize * self.height as usize;
        match self.pixels {
            RectPixels::Color { .. } => 4 * n,
            RectPixels::Depth { .. } => 4 * n,
            RectPixels::Stencil { z: None, .. } => n,
            RectPixels::Stencil { z: Some(_), .. } => 5 * n,
        }
    }
}

/// What `glDrawPixels` draws: its `format` decides (`GL_STENCIL_INDEX`,
/// `GL_DEPTH_COMPONENT`, `GL_COLOR_INDEX`, or a colour format).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawKind {
    /// The colour format of the data.
    Color,
    /// Colour indices (one component), through the `I_TO_*` maps.
    Index,
    Depth,
    Stencil,
    /// `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil): depth and stencil at once.
    DepthStencil,
}

/// `glCopyPixels`' `type`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CopyKind {
    Color,
    Depth,
    Stencil,
    /// `GL_DEPTH_STENCIL` (EXT_packed_depth_stencil).
    DepthStencil,
}

/// A unorm8 texel as llvmpipe samples it: times `1/255` (not divided by
/// 255: 194 then gives 0.7607844, which scaled and biased by −0.5 rounds
/// to 67, not 66, as in llvmpipe).
fn unorm8_to_f32(u: u8) -> f32 {
    f32::from(u) * (1.0 / 255.0)
}

/// Depth `d` as llvmpipe's fragments read it back from the texture Mesa
/// puts the image in (`make_texture`, `st_cb_drawpixels.c`): 16 bits for
/// 8- and 16-bit types (a `Z16_UNORM` texture, so scale and bias, applied
/// before, are rounded to 16 bits), sampled as `v·(1/65535)`; the others as they are.
fn through_texture(d: f32, ty: crate::PixelType) -> f32 {
    use crate::PixelType as T;
    match ty {
        T::UnsignedByte | T::Byte | T::UnsignedShort | T::Short => {
            crate::framebuffer::float_to_unorm(d, 65535) as f32 * (1.0 / 65535.0)
        }
        _ => d,
    }
}

/// A stored depth `d` of a buffer of `format` (a float format's is its float), as
/// llvmpipe samples a depth texture: `d·(1/max)` in f32 (which does not
/// give `d` back for about a third of 24-bit values).
fn sampled_depth(d: u32, format: Option<softgl_jit::DepthFormat>) -> f32 {
    match format {
        Some(softgl_jit::DepthFormat::D32F) => f32::from_bits(d),
        Some(f) => d as f32 * (1.0 / f.max_value() as f32),
        None => 0.0,
    }
}

/// A one-component integer value (an index or a stencil value) as read.
fn integer(raw: crate::texture::unpack::Raw) -> i64 {
    use crate::texture::unpack::Raw;
    match raw {
        Raw::U(v, _) => i64::from(v),
        Raw::S(v, _) => i64::from(v),
        Raw::F(f) if f.is_finite() => f.clamp(-1e15, 1e15) as i64,
        Raw::F(_) => 0,
    }
}

/// Depth `z` (window, `[0, 1]`) in the buffer units of `format`, as llvmpipe
/// converts a fragment's depth (f32; 32-bit depth as triangles do).
fn depth_units(z: f32, format: Option<softgl_jit::DepthFormat>) -> u32 {
    match format {
        Some(f @ softgl_jit::DepthFormat::D32) => crate::raster::depth_value(f64::from(z), Some(f)),
        Some(f) => f.from_window(z),
        None => 0,
    }
}

impl Context {
    /// The pixel zoom, transfer parameters and maps.
    pub fn pixel_state(&self) -> &crate::pixel_transfer::PixelState {
        &self.pixel
    }

    /// `glPixelZoom`.
    pub fn pixel_zoom(&mut self, x: f32, y: f32) -> GlResult {
        self.outside()?;
        self.pixel.zoom = [x, y];
        Ok(())
    }

    /// `glPixelTransfer`.
    pub fn pixel_transfer(&mut self, p: crate::pixel_transfer::PixelTransferParam) -> GlResult {
        self.outside()?;
        self.pixel.set(p);
        Ok(())
    }

    /// `glPixelMap`.
    pub fn pixel_map(&mut self, name: crate::pixel_transfer::PixelMapName, values: &[f32]) -> GlResult {
        self.outside()?;
        let r = self.pixel.set_map(name, values);
        self.record(r)
    }

    /// Puts back the whole pixel state (`glPopAttrib(GL_PIXEL_MODE_BIT)`).
    pub fn set_pixel_state(&mut self, p: crate::pixel_transfer::PixelState) -> GlResult {
        self.outside()?;
        self.pixel = p;
        Ok(())
    }

    /// `glDrawPixels`: `width`×`height` pixels of `data` (its format read
    /// as `kind` says; depth, stencil and index data have one component,
    /// `data.format` is then ignored) drawn at the raster position with the
    /// pixel zoom, after the pixel transfer operations, then textured,
    /// colour-summed and fogged at the raster position ([`PixelShade`]).
    /// Nothing at an invalid raster position.
    pub fn draw_pixels(&mut self, width: i32, height: i32, kind: DrawKind, data: &crate::PixelData<'_>) -> GlResult {
        use crate::texture::unpack::{fetch, ClientLayout, Raw};
        self.outside()?;
        self.acquire_deferred();
        self.require(width >= 0 && height >= 0)?;
        let fb = &self.fb;
        let missing = match kind {
            DrawKind::Depth => fb.depth_format().is_none(),
            DrawKind::Stencil => !fb.has_stencil(),
            DrawKind::DepthStencil => fb.depth_format().is_none() || !fb.has_stencil(),
            _ => false,
        };
        if missing {
            return self.record(Err(GlError::InvalidOperation));
        }
        if !self.raster.valid || self.pixels_not_rendered(crate::select::token::DRAW_PIXEL) {
            return Ok(());
        }
        if width == 0 || height == 0 {
            return Ok(());
        }
        let format = match kind {
            DrawKind::Color => data.format,
            DrawKind::DepthStencil => crate::PixelFormat::DepthStencil,
            _ => crate::PixelFormat::DepthComponent,
        };
        let (w, h) = (width as usize, height as usize);
        let layout = ClientLayout::new(format, data.ty, &data.store, 2, [w, h, 1]);
        let Some(layout) = layout.filter(|l| l.len <= data.bytes.len()) else {
            return self.record(Err(GlError::InvalidOperation));
        };
        let swap = data.store.swap_bytes;
        let get = |i: usize, j: usize| fetch(data.bytes, layout.at(i, j, 0), format, data.ty, swap);
        let depth_format = self.fb.depth_format();
        let p = &self.pixel;
        let raster_z = self.raster.window[2];
        let pixels = match kind {
            DrawKind::Color | DrawKind::Index => {
                let mut rgba = Vec::with_capacity(w * h);
                for j in 0..h {
                    for i in 0..w {
                        let raw = get(i, j);
                        let c = match kind {
                            DrawKind::Index => p.index_colour(integer(raw[0])),
                            // Components of 8 bits or fewer become unorm8 first, their
                            // bits replicated (Mesa's `_mesa_unorm_to_unorm` into the
                            // image's RGBA8 texture: 5 bits 24 → 198, not 197),
                            // sampled as llvmpipe samples unorm8.
                            _ => p.colour(raw.map(|r| match r {
                                Raw::U(_, b) if b <= 8 => unorm8_to_f32(r.to_unorm(8) as u8),
                                r => r.to_f32(),
                            })),
                        };
                        rgba.push(c.map(softgl_jit::shade::unorm8));
                    }
                }
                RectPixels::Color {
                    rgba: Arc::from(rgba),
                    z: depth_units(raster_z, depth_format),
                }
            }
            DrawKind::Depth => {
                let mut z = Vec::with_capacity(w * h);
                for j in 0..h {
                    for i in 0..w {
                        let d = p.depth(get(i, j)[0].to_f32());
                        z.push(depth_units(through_texture(d, data.ty), depth_format));
                    }
                }
                let c = self.raster.color.to_array();
                RectPixels::Depth {
                    z: Arc::from(z),
                    rgba: c.map(softgl_jit::shade::unorm8),
                }
            }
            DrawKind::Stencil => {
                let mut s = Vec::with_capacity(w * h);
                for j in 0..h {
                    for i in 0..w {
                        s.push(p.stencil(integer(get(i, j)[0])) as u8);
                    }
                }
                RectPixels::Stencil {
                    s: Arc::from(s),
                    write_mask: self.state.stencil_write_mask as u8,
                    scissor: self.scissor_rect(),
                    z: None,
                }
            }
            DrawKind::DepthStencil => {
                let (mut s, mut z) = (Vec::with_capacity(w * h), Vec::with_capacity(w * h));
                for j in 0..h {
                    for i in 0..w {
                        let raw = get(i, j);
                        s.push(p.stencil(integer(raw[1])) as u8);
                        let d = p.depth(raw[0].to_f32());
                        z.push(depth_units(through_texture(d, data.ty), depth_format));
                    }
                }
                RectPixels::Stencil {
                    s: Arc::from(s),
                    write_mask: self.state.stencil_write_mask as u8,
                    scissor: self.scissor_rect(),
                    z: self.state.depth_write.then(|| Arc::from(z)),
                }
            }
        };
        self.place(pixels, (width as u32, height as u32))
    }

    /// `glDrawPixels` with type `GL_BITMAP`: each bit of `image` is a colour
    /// index (`kind` [`DrawKind::Index`]) or a stencil value
    /// ([`DrawKind::Stencil`]) of 0 or 1, then drawn as [`Self::draw_pixels`]
    /// draws indices. Other kinds are `InvalidEnum`.
    pub fn draw_pixels_bitmap(&mut self, image: &BitmapImage, kind: DrawKind) -> GlResult {
        self.outside()?;
        self.acquire_deferred();
        match kind {
            DrawKind::Index => {}
            DrawKind::Stencil if self.fb.has_stencil() => {}
            DrawKind::Stencil => return self.record(Err(GlError::InvalidOperation)),
            _ => return self.record(Err(GlError::InvalidEnum)),
        }
        let (w, h) = (image.width, image.height);
        if !self.raster.valid || self.pixels_not_rendered(crate::select::token::DRAW_PIXEL) || w == 0 || h == 0 {
            return Ok(());
        }
        let bits = (0..h).flat_map(|j| (0..w).map(move |i| i64::from(image.get(i, j))));
        let p = &self.pixel;
        let pixels = match kind {
            DrawKind::Stencil => RectPixels::Stencil {
                s: Arc::from(bits.map(|b| p.stencil(b) as u8).collect::<Vec<_>>()),
                write_mask: self.state.stencil_write_mask as u8,
                scissor: self.scissor_rect(),
                z: None,
            },
            _ => RectPixels::Color {
                rgba: Arc::from(
                    bits.map(|b| p.index_colour(b).map(softgl_jit::shade::unorm8))
                        .collect::<Vec<_>>(),
                ),
                z: depth_units(self.raster.window[2], self.fb.depth_format()),
            },
        };
        self.place(pixels, (w, h))
    }

    /// Outside render mode a pixel rectangle is not drawn: its `token` and
    /// the raster position go to the feedback buffer ([`crate::select`]).
    fn pixels_not_rendered(&mut self, token: f32) -> bool {
        let r = self.raster;
        self.render_mode.raster_primitive(token, &r)
    }

    /// The scissor box as a rectangle of the framebuffer, when the test is on.
    fn scissor_rect(&self) -> Option<Rect> {
        let s = &self.state;
        s.scissor_test.then(|| {
            let b = s.scissor;
            self.fb
                .clip_rect(i64::from(b.x), i64::from(b.y), i64::from(b.width), i64::from(b.height))
        })
    }

    /// Records `pixels` (`size` source pixels) at the raster position, rounded
    /// as Mesa rounds it (`lroundf`), with the pixel zoom.
    fn place(&mut self, pixels: RectPixels, (width, height): (u32, u32)) -> GlResult {
        let [rx, ry, ..] = self.raster.window;
        let zoom = self.pixel.zoom;
        let (x, y) = (rx.round(), ry.round());
        let image = PlacedImage {
            pixels,
            width,
            height,
            x,
            y,
            zoom,
        };
        let (state, params, vertex, shade) = self.raster_draw(true)?;
        let mut image = image;
        if let Some(shade) = shade {
            image.pixels = match image.pixels {
                RectPixels::Color { rgba, z } => RectPixels::Color {
                    rgba: rgba.iter().map(|&c| shade.apply(c)).collect(),
                    z,
                },
                RectPixels::Depth { z, rgba } => RectPixels::Depth {
                    z,
                    rgba: shade.apply(rgba),
                },
                stencil @ RectPixels::Stencil { .. } => stencil,
            };
        }
        let saved = self.one_sample_tests(image.rect(params.bounds));
        for (scene, fb) in self.lane_scenes() {
            scene.pixels(state.clone(), &params, vertex, image.clone(), fb);
        }
        self.scene.pixels(state, &params, vertex, image, &self.fb);
        self.end_one_sample_tests(saved);
        Ok(())
    }

    /// Before a bitmap or pixel rectangle covering `rect` is recorded: in a
    /// multisampled framebuffer with the depth or stencil test on, every
    /// draw so far is rasterized and samples 1.. take sample 0's depth and
    /// stencil there (llvmpipe tests them in sample 0 only:
    /// [`Framebuffer::tests_from_sample0`]). Such a draw is rasterized at
    /// once, in [`Context::end_one_sample_tests`] (Mesa's bitmap cache then
    /// merges no glyphs: the bytes differ only where glyphs overlap).
    pub(crate) fn one_sample_tests(&mut self, rect: Option<Rect>) -> Option<crate::multisample::SavedTests> {
        let s = &self.state;
        if self.fb.samples() == 1 || !(s.depth_test || s.stencil_test) {
            return None;
        }
        let rect = rect?;
        self.finish_scene();
        Some(self.fb.tests_from_sample0(rect))
    }

    /// After the draw [`Context::one_sample_tests`] prepared: rasterizes it
    /// and puts samples 1..'s depth and stencil back; otherwise flushes the
    /// scene when it is over its bound.
    pub(crate) fn end_one_sample_tests(&mut self, saved: Option<crate::multisample::SavedTests>) {
        match saved {
            Some(saved) => {
                self.finish_scene();
                self.fb.restore_tests(saved);
                // Sample 0 alone may have been written.
                self.samples_same = [None; 2];
            }
            None if self.scene.bytes() > self.scene.bound() => self.finish_scene(),
            None => {}
        }
    }

    /// `glCopyPixels`: the `width`×`height` rectangle at window `(x, y)` of
    /// the framebuffer as it is now, drawn as `glDrawPixels` draws (the
    /// source read whole first, so that overlapping copies read what was
    /// there before). Source pixels outside the framebuffer are not drawn.
    pub fn copy_pixels(&mut self, x: i32, y: i32, width: i32, height: i32, kind: CopyKind) -> GlResult {
        self.outside()?;
        self.acquire_deferred();
        self.require(width >= 0 && height >= 0)?;
        // From a multisampled object: Mesa's `_mesa_CopyPixels`.
        if self.fbo.read != 0 && self.samples_of(self.fbo.read) > 0 {
            return self.record(Err(GlError::InvalidOperation));
        }
        let missing = match kind {
            CopyKind::Depth => self.fb.depth_format().is_none(),
            CopyKind::Stencil => !self.fb.has_stencil(),
            CopyKind::DepthStencil => self.fb.depth_format().is_none() || !self.fb.has_stencil(),
            CopyKind::Color => false,
        };
        if missing {
            return self.record(Err(GlError::InvalidOperation));
        }
        if !self.raster.valid || self.pixels_not_rendered(crate::select::token::COPY_PIXEL) {
            return Ok(());
        }
        // The source clipped to the framebuffer; the destination moves with it.
        let (fw, fh) = (i64::from(self.fb.width()), i64::from(self.fb.height()));
        let (x0, y0) = (i64::from(x).max(0), i64::from(y).max(0));
        let x1 = (i64::from(x) + i64::from(width)).min(fw);
        let y1 = (i64::from(y) + i64::from(height)).min(fh);
        if x0 >= x1 || y0 >= y1 {
            return Ok(());
        }
        self.finish_scene();
        let (w, h) = ((x1 - x0) as u32, (y1 - y0) as u32);
        let (dx, dy) = ((x0 - i64::from(x)) as f32, (y0 - i64::from(y)) as f32);
        let fb = &self.fb;
        let p = &self.pixel;
        let depth_format = fb.depth_format();
        let coords = (y0..y1).flat_map(|j| (x0..x1).map(move |i| (i as u32, j as u32)));
        let raster_z = self.raster.window[2];
        let pixels = match kind {
            CopyKind::Color => {
                let rgba = coords
                    .map(|(i, j)| {
                        let c = fb.pixel(i, j).unwrap_or_default();
                        if p.scales_or_biases() || p.map_color {
                            p.colour(c.map(unorm8_to_f32)).map(softgl_jit::shade::unorm8)
                        } else {
                            c
                        }
                    })
                    .collect::<Vec<_>>();
                RectPixels::Color {
                    rgba: Arc::from(rgba),
                    z: depth_units(raster_z, depth_format),
                }
            }
            CopyKind::Depth => {
                let z = coords
                    .map(|(i, j)| {
                        let d = sampled_depth(fb.depth_at(i, j).unwrap_or(0), depth_format);
                        let d = if p.depth_scale == 1.0 && p.depth_bias == 0.0 {
                            d
                        } else {
                            p.depth(d)
                        };
                        depth_units(d, depth_format)
                    })
                    .collect::<Vec<_>>();
                let c = self.raster.color.to_array();
                RectPixels::Depth {
                    z: Arc::from(z),
                    rgba: c.map(softgl_jit::shade::unorm8),
                }
            }
            CopyKind::Stencil => {
                let s = coords
                    .map(|(i, j)| p.stencil(i64::from(fb.stencil_at(i, j).unwrap_or(0))) as u8)
                    .collect::<Vec<_>>();
                RectPixels::Stencil {
                    s: Arc::from(s),
                    write_mask: self.state.stencil_write_mask as u8,
                    scissor: self.scissor_rect(),
                    z: None,
                }
            }
            CopyKind::DepthStencil => {
                let (mut s, mut z) = (Vec::new(), Vec::new());
                for (i, j) in coords {
                    s.push(p.stencil(i64::from(fb.stencil_at(i, j).unwrap_or(0))) as u8);
                    let d = sampled_depth(fb.depth_at(i, j).unwrap_or(0), depth_format);
                    let d = if p.depth_scale == 1.0 && p.depth_bias == 0.0 {
                        d
                    } else {
                        p.depth(d)
                    };
                    z.push(depth_units(d, depth_format));
                }
                RectPixels::Stencil {
                    s: Arc::from(s),
                    write_mask: self.state.stencil_write_mask as u8,
                    scissor: self.scissor_rect(),
                    z: self.state.depth_write.then(|| Arc::from(z)),
                }
            }
        };
        let zoom = self.pixel.zoom;
        let saved = self.raster.window;
        self.raster.window[0] += dx * zoom[0];
        self.raster.window[1] += dy * zoom[1];
        let r = self.place(pixels, (w, h));
        self.raster.window = saved;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{FramebufferDesc, PixelStore};

    #[test]
    fn unpacking_follows_the_unpack_state() {
        // 10×2, MSB first, alignment 1: rows of 2 bytes.
        let data = [0b1000_0001, 0b0100_0000, 0b1111_1111, 0b1100_0000];
        let store = PixelStore {
            alignment: 1,
            ..PixelStore::DEFAULT
        };
        let b = BitmapImage::unpack(10, 2, &data, &store).unwrap();
        let row = |y| (0..10).map(|x| b.get(x, y) as u8).collect::<Vec<_>>();
        assert_eq!(row(0), [1, 0, 0, 0, 0, 0, 0, 1, 0, 1]);
        assert_eq!(row(1), [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]);
        // LSB first, skipping one pixel and one row, alignment 4.
        let store = PixelStore {
            lsb_first: true,
            skip_pixels: 1,
            skip_rows: 1,
            ..PixelStore::DEFAULT
        };
        let data = [0, 0, 0, 0, 0b0000_0110, 0, 0, 0];
        assert_eq!(BitmapImage::client_bytes(3, 1, &store), Some(5));
        let b = BitmapImage::unpack(3, 1, &data, &store).unwrap();
        assert_eq!((0..3).map(|x| b.get(x, 0)).collect::<Vec<_>>(), [true, true, false]);
        assert_eq!(
            BitmapImage::unpack(3, 1, &data[..4], &store),
            Err(GlError::InvalidOperation)
        );
        assert_eq!(BitmapImage::unpack(-1, 1, &data, &store), Err(GlError::InvalidValue));
    }

    #[test]
    fn a_bitmap_draws_its_bits_in_the_raster_colour_and_moves() {
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(80, 70)).unwrap();
        gl.ortho(0.0, 80.0, 0.0, 70.0, -1.0, 1.0).unwrap();
        gl.color3(1.0, 0.0, 0.0);
        gl.raster_pos(10.0, 20.0, 0.0, 1.0).unwrap();
        gl.color3(0.0, 1.0, 0.0);
        // 70 wide: two words a row; a checker of its first row.
        let mut data = vec![0u8; 9 * 2];
        data[0] = 0b1010_0000;
        data[8] = 0b0100_0000;
        data[9] = 0xff;
        let store = PixelStore {
            alignment: 1,
            ..PixelStore::DEFAULT
        };
        let b = BitmapImage::unpack(70, 2, &data, &store).unwrap();
        gl.bitmap(&b, [2.0, 0.0], [5.0, 1.0]).unwrap();
        assert_eq!(gl.raster_position().window[..2], [15.0, 21.0]);
        let fb = gl.framebuffer();
        let red = Some([255, 0, 0, 255]);
        let black = Some([0, 0, 0, 0]);
        assert_eq!(fb.pixel(8, 20), red);
        assert_eq!(fb.pixel(9, 20), black);
        assert_eq!(fb.pixel(10, 20), red);
        assert_eq!(fb.pixel(8 + 65, 20), red);
        assert_eq!(fb.pixel(8 + 64, 20), black);
        assert_eq!(fb.pixel(8, 21), red);
        assert_eq!(fb.pixel(15, 21), red);
        assert_eq!(fb.pixel(16, 21), black);
        // Invalid: nothing, and no move.
        gl.raster_pos(100.0, 20.0, 0.0, 1.0).unwrap();
        gl.bitmap(&b, [0.0, 0.0], [5.0, 1.0]).unwrap();
        assert_eq!(gl.raster_position().window[..2], [15.0, 21.0]);
    }
}

#[cfg(test)]
mod pixel_tests {
    use super::*;
    use crate::pixel_transfer::{PixelMapName, PixelTransferParam};
    use crate::{Capability, FramebufferDesc, PixelData, PixelFormat, PixelStore, PixelType};

    fn ctx(backend: Backend) -> Context {
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(40, 30)).unwrap();
        gl.set_backend(backend);
        gl.ortho(0.0, 40.0, 0.0, 30.0, -1.0, 1.0).unwrap();
        gl
    }

    fn data(format: PixelFormat, bytes: &[u8]) -> PixelData<'_> {
        PixelData {
            format,
            ty: PixelType::UnsignedByte,
            store: PixelStore {
                alignment: 1,
                ..PixelStore::DEFAULT
            },
            bytes,
        }
    }

    /// A 3×2 RGB image: pixel (i, j) is (10i, 10j, 7).
    fn image() -> Vec<u8> {
        (0..2)
            .flat_map(|j| (0..3).flat_map(move |i| [10 * i, 10 * j, 7]))
            .collect()
    }

    #[test]
    fn zoom_places_and_repeats_source_pixels() {
        let mut gl = ctx(Backend::Interpreter);
        gl.raster_pos(10.0, 10.0, 0.0, 1.0).unwrap();
        gl.pixel_zoom(2.0, -1.0).unwrap();
        let img = image();
        gl.draw_pixels(3, 2, DrawKind::Color, &data(PixelFormat::Rgb, &img))
            .unwrap();
        let fb = gl.framebuffer();
        // Columns 10..16, each source column twice; rows 9 (source row 0) and 8.
        assert_eq!(fb.pixel(10, 9), Some([0, 0, 7, 255]));
        assert_eq!(fb.pixel(11, 9), Some([0, 0, 7, 255]));
        assert_eq!(fb.pixel(12, 9), Some([10, 0, 7, 255]));
        assert_eq!(fb.pixel(15, 8), Some([20, 10, 7, 255]));
        assert_eq!(fb.pixel(16, 9), Some([0, 0, 0, 0]));
        assert_eq!(fb.pixel(10, 10), Some([0, 0, 0, 0]));
        assert_eq!(fb.pixel(10, 7), Some([0, 0, 0, 0]));
    }

    #[test]
    fn stencil_images_take_shift_offset_map_write_mask_and_scissor() {
        let mut gl = ctx(Backend::Interpreter);
        gl.raster_pos(0.0, 0.0, 0.0, 1.0).unwrap();
        gl.pixel_transfer(PixelTransferParam::IndexShift(1)).unwrap();
        gl.pixel_transfer(PixelTransferParam::IndexOffset(3)).unwrap();
        gl.stencil_mask(0x0f).unwrap();
        gl.enable(Capability::ScissorTest).unwrap();
        gl.scissor(1, 0, 10, 10).unwrap();
        let s = [1u8, 2, 100];
        gl.draw_pixels(3, 1, DrawKind::Stencil, &data(PixelFormat::DepthComponent, &s))
            .unwrap();
        let fb = gl.framebuffer();
        assert_eq!(fb.stencil_at(0, 0), Some(0), "outside the scissor box");
        assert_eq!(fb.stencil_at(1, 0), Some((2 * 2 + 3) & 0x0f));
        assert_eq!(fb.stencil_at(2, 0), Some((2 * 100 + 3) & 0x0f));
        gl.disable(Capability::ScissorTest).unwrap();
        gl.pixel_map(PixelMapName::SToS, &[5.0, 6.0]).unwrap();
        gl.pixel_transfer(PixelTransferParam::MapStencil(true)).unwrap();
        gl.stencil_mask(0xff).unwrap();
        gl.draw_pixels(3, 1, DrawKind::Stencil, &data(PixelFormat::DepthComponent, &s))
            .unwrap();
        // (1·2 + 3) & 1 = 1 → 6; (2·2 + 3) & 1 = 1 → 6.
        assert_eq!(gl.framebuffer().stencil_at(0, 0), Some(6));
    }

    #[test]
    fn depth_images_are_scaled_biased_and_depth_tested() {
        let mut gl = ctx(Backend::Interpreter);
        gl.raster_pos(0.0, 0.0, 0.0, 1.0).unwrap();
        gl.pixel_transfer(PixelTransferParam::DepthScale(0.5)).unwrap();
        gl.pixel_transfer(PixelTransferParam::DepthBias(0.25)).unwrap();
        let z = [0.0f32, 1.0];
        let bytes: Vec<u8> = z.iter().flat_map(|v| v.to_ne_bytes()).collect();
        let d = PixelData {
            ty: PixelType::Float,
            ..data(PixelFormat::DepthComponent, &bytes)
        };
        gl.enable(Capability::DepthTest).unwrap();
        gl.draw_pixels(2, 1, DrawKind::Depth, &d).unwrap();
        let max = 16_777_215.0f32;
        let fb = gl.framebuffer();
        assert_eq!(fb.depth_at(0, 0), Some((0.25 * max).round_ties_even() as u32));
        assert_eq!(fb.depth_at(1, 0), Some((0.75 * max).round_ties_even() as u32));
        // The raster colour is the fragments'.
        assert_eq!(fb.pixel(0, 0), Some([255, 255, 255, 255]));
    }

    #[test]
    fn overlapping_copies_read_the_source_first() {
        let mut gl = ctx(Backend::Interpreter);
        gl.raster_pos(0.0, 0.0, 0.0, 1.0).unwrap();
        let img = image();
        gl.draw_pixels(3, 2, DrawKind::Color, &data(PixelFormat::Rgb, &img))
            .unwrap();
        gl.raster_pos(1.0, 0.0, 0.0, 1.0).unwrap();
        gl.copy_pixels(0, 0, 3, 2, CopyKind::Color).unwrap();
        let fb = gl.framebuffer();
        let row: Vec<_> = (0..4).map(|x| fb.pixel(x, 1).unwrap()[0]).collect();
        assert_eq!(row, [0, 0, 10, 20]);
        // Invalid raster position: nothing.
        gl.raster_pos(-5.0, 0.0, 0.0, 1.0).unwrap();
        gl.copy_pixels(0, 0, 3, 2, CopyKind::Color).unwrap();
        assert_eq!(gl.framebuffer().pixel(1, 1).unwrap()[0], 0);
        assert_eq!(gl.copy_pixels(0, 0, -1, 2, CopyKind::Color), Err(GlError::InvalidValue));
    }

    #[test]
    fn bitmap_typed_images_are_one_bit_indices() {
        let mut gl = ctx(Backend::Interpreter);
        gl.pixel_map(PixelMapName::IToR, &[0.0, 1.0]).unwrap();
        gl.pixel_map(PixelMapName::IToA, &[1.0, 1.0]).unwrap();
        gl.raster_pos(2.0, 3.0, 0.0, 1.0).unwrap();
        let b = BitmapImage::unpack(3, 1, &[0b1010_0000], &PixelStore::DEFAULT).unwrap();
        gl.draw_pixels_bitmap(&b, DrawKind::Index).unwrap();
        gl.draw_pixels_bitmap(&b, DrawKind::Stencil).unwrap();
        assert_eq!(gl.draw_pixels_bitmap(&b, DrawKind::Depth), Err(GlError::InvalidEnum));
        let fb = gl.framebuffer();
        let reds: Vec<_> = (2..5).map(|x| fb.pixel(x, 3).unwrap()).collect();
        assert_eq!(reds, [[255, 0, 0, 255], [0, 0, 0, 255], [255, 0, 0, 255]]);
        let s: Vec<_> = (2..5).map(|x| fb.stencil_at(x, 3).unwrap()).collect();
        assert_eq!(s, [1, 0, 1]);
    }

    /// Bitmaps and pixel rectangles through blending and the depth test:
    /// the specialists leave the same bytes as the interpreter.
    #[test]
    fn the_jit_equals_the_interpreter() {
        let draw = |backend| {
            let mut gl = ctx(backend);
            gl.clear_color(0.2, 0.4, 0.6, 0.8).unwrap();
            gl.clear(crate::ClearMask::COLOR).unwrap();
            gl.enable(Capability::Blend).unwrap();
            gl.blend_func(crate::BlendFactor::SrcAlpha, crate::BlendFactor::OneMinusSrcAlpha)
                .unwrap();
            gl.color4(0.9, 0.3, 0.1, 0.6);
            gl.raster_pos(3.0, 4.0, 0.0, 1.0).unwrap();
            let bits: Vec<u8> = (0..13 * 2).map(|i| (i * 37 + 11) as u8).collect();
            let b = BitmapImage::unpack(16, 13, &bits, &data(PixelFormat::Rgb, &[]).store).unwrap();
            gl.bitmap(&b, [0.0, 0.0], [9.0, 0.0]).unwrap();
            let rgba: Vec<u8> = (0..20 * 10 * 4).map(|i| (i * 13 + 5) as u8).collect();
            gl.pixel_zoom(1.5, 1.0).unwrap();
            gl.draw_pixels(20, 10, DrawKind::Color, &data(PixelFormat::Rgba, &rgba))
                .unwrap();
            gl.framebuffer().color_bytes().to_vec()
        };
        assert_eq!(draw(Backend::Jit), draw(Backend::Interpreter));
    }
}
