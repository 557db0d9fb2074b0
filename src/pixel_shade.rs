//! The shading stage of pixel rectangles (GL 1.5 §3.6.5, §3.7): the
//! fragments of `glDrawPixels` and `glCopyPixels` take the raster
//! position's texture coordinates, secondary colour and distance, and go
//! through the texture environment, the colour sum and fog like any
//! fragment, their primary colour being the image's.
//!
//! Every fragment of a rectangle has the same texture coordinates, so ρ is
//! 0 (magnification) and each unit's sample is one constant: the stage is
//! run on the CPU once a source pixel when the rectangle is recorded, and
//! the fragment specialist (interpreter or JIT alike) gets the shaded
//! colours in its spans. A rectangle with no such stage on costs one check.
//!
//! llvmpipe departs from GL here (`docs/llvmpipe-facts.md` §26): texture
//! unit 0 reads the image's own coordinates, no secondary colour and fog
//! coordinate 0; softgl follows GL, which agrees with llvmpipe whenever the
//! textures are uniform and colour sum and fog are off.

use crate::texture::unit::TexturePlan;
use glam::Vec4;
use softgl_jit::key::ShadeKey;
use softgl_jit::shade::{shade, unorm8, FogMode, FogUniforms};
use softgl_jit::texture::MAX_UNITS;

/// The stage a rectangle's colours go through, its constants evaluated.
#[derive(Clone, Debug)]
pub struct PixelShade {
    /// The key's texture units (`None`: not sampled).
    units: [Option<softgl_jit::texture::TexUnitKey>; MAX_UNITS],
    /// Each unit's sample at the raster position's coordinates.
    samples: [[f32; 4]; MAX_UNITS],
    env_color: [[f32; 4]; MAX_UNITS],
    textured: bool,
    secondary: Option<[f32; 3]>,
    fog: Option<(FogMode, f32, FogUniforms)>,
}

impl PixelShade {
    /// The stage of `key` (a draw's, made now) at a raster position with
    /// texture coordinates `tex_coords`, secondary colour `secondary` and
    /// distance `distance`; `None` when it would leave colours as they are
    /// (no texture unit, no colour sum, no fog, or nothing reads colour).
    pub fn new(
        key: Option<&ShadeKey>,
        textures: &TexturePlan<'_>,
        (tex_coords, secondary, distance): (&[Vec4; MAX_UNITS], Vec4, f32),
        fog: FogUniforms,
    ) -> Option<PixelShade> {
        let key = key.filter(|k| k.color)?;
        let textured = key.textured();
        if !(textured || key.color_sum || key.fog.is_some()) {
            return None;
        }
        let set = textures.set();
        let mut samples = [[0.0; 4]; MAX_UNITS];
        for (u, unit) in key.tex.iter().enumerate() {
            if let (Some(unit), Some(tex)) = (unit, &set.units[u]) {
                // The same coordinates at the quad's four pixels: no derivatives.
                let c = tex_coords[u].to_array();
                samples[u] = softgl_jit::texture::sample_quad(unit, tex, &[c; 4], 0);
            }
        }
        let clamp = |v: f32| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        Some(PixelShade {
            units: key.tex,
            samples,
            env_color: set.env_color,
            textured,
            secondary: key
                .color_sum
                .then(|| [secondary.x, secondary.y, secondary.z].map(clamp)),
            fog: key.fog.map(|m| (m, distance, fog)),
        })
    }

    /// The fragment colour of an image colour `c` (unorm8).
    pub fn apply(&self, c: [u8; 4]) -> [u8; 4] {
        let mut primary = c.map(|v| f32::from(v) * (1.0 / 255.0));
        if self.textured {
            primary = softgl_jit::texture::environment(&self.units, &self.samples, primary, &self.env_color);
        }
        let fog = self.fog.as_ref().map(|(m, d, u)| (*m, *d, u));
        shade(primary, self.secondary, fog).map(unorm8)
    }
}

#[cfg(test)]
mod tests {
    use crate::fog::{FogCoordSrc, FogParam};
    use crate::pixel_rect::{BitmapImage, CopyKind, DrawKind};
    use crate::texture::{EnvMode, Filter, InternalFormat, MipFilter, TexImageTarget, TexParam};
    use crate::{Backend, Capability, Context, FramebufferDesc, PixelData, PixelStore};
    use crate::{TexEnvParam, TextureTarget};
    use softgl_jit::shade::FogMode;

    fn ctx(backend: Backend) -> Context {
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(16, 16)).unwrap();
        gl.set_backend(backend);
        gl.ortho(0.0, 16.0, 0.0, 16.0, -1.0, 1.0).unwrap();
        gl
    }

    fn rgba(bytes: &[u8]) -> PixelData<'_> {
        PixelData::rgba8(bytes)
    }

    /// A 2×2 texture of `texels` (RGBA8, nearest) on unit 0, enabled, in `mode`.
    fn texture(gl: &mut Context, texels: &[u8; 16], mode: EnvMode) {
        let t = TextureTarget::D2;
        let name = gl.gen_textures(1).unwrap()[0];
        gl.bind_texture(t, name).unwrap();
        gl.tex_image(
            TexImageTarget::D2,
            0,
            InternalFormat::Rgba8,
            [2, 2, 1],
            0,
            Some(rgba(texels)),
        )
        .unwrap();
        gl.tex_parameter(t, TexParam::MinFilter(Filter::Nearest, MipFilter::None))
            .unwrap();
        gl.tex_parameter(t, TexParam::MagFilter(Filter::Nearest)).unwrap();
        gl.tex_env(TexEnvParam::Mode(mode)).unwrap();
        gl.enable(Capability::Texture(t)).unwrap();
    }

    /// piglit's `draw-pixel-with-texture`: an image of (0.2, 1, 0, 1)
    /// modulated by a red texture is (0.2, 0, 0, 1); the texel is the one
    /// at the raster position's coordinates (latched at `glRasterPos`).
    #[test]
    fn draw_pixels_are_textured_at_the_raster_coordinates() {
        for backend in [Backend::Interpreter, Backend::Jit] {
            let mut gl = ctx(backend);
            // Texel (1, 1) blue, the others red.
            let mut texels = [255, 0, 0, 255].repeat(4);
            texels[12..16].copy_from_slice(&[0, 0, 255, 255]);
            texture(&mut gl, &texels.try_into().unwrap(), EnvMode::Modulate);
            gl.tex_coord4(0.25, 0.25, 0.0, 1.0);
            gl.raster_pos(1.0, 1.0, 0.0, 1.0).unwrap();
            gl.tex_coord4(0.75, 0.75, 0.0, 1.0);
            let img = [51u8, 255, 0, 255].repeat(4);
            gl.draw_pixels(2, 2, DrawKind::Color, &rgba(&img)).unwrap();
            // At the second raster position, texel (1, 1): blue × image.
            gl.raster_pos(5.0, 1.0, 0.0, 1.0).unwrap();
            gl.draw_pixels(2, 2, DrawKind::Color, &rgba(&img)).unwrap();
            // A copy of the first rectangle, textured again (blue × red = 0).
            gl.raster_pos(9.0, 1.0, 0.0, 1.0).unwrap();
            gl.copy_pixels(1, 1, 2, 2, CopyKind::Color).unwrap();
            let fb = gl.framebuffer();
            assert_eq!(fb.pixel(1, 1), Some([51, 0, 0, 255]), "{backend:?}");
            assert_eq!(fb.pixel(2, 2), Some([51, 0, 0, 255]), "{backend:?}");
            assert_eq!(fb.pixel(5, 1), Some([0, 0, 0, 255]), "{backend:?}");
            assert_eq!(fb.pixel(9, 2), Some([0, 0, 0, 255]), "{backend:?}");
            assert_eq!(fb.pixel(3, 1), Some([0, 0, 0, 0]), "{backend:?}");
        }
    }

    /// Fog at the raster distance (linear, start 0, end 10: distance 7.5
    /// leaves f = 0.25 of the colour, 255 → 63.75 → 64 over black fog);
    /// colour sum adds the raster secondary colour; alpha is not fogged.
    /// Bitmaps and pixel rectangles alike, both back ends.
    #[test]
    fn pixel_rectangles_and_bitmaps_take_colour_sum_and_fog() {
        for backend in [Backend::Interpreter, Backend::Jit] {
            let mut gl = ctx(backend);
            gl.enable(Capability::Fog).unwrap();
            gl.fog(FogParam::Mode(FogMode::Linear)).unwrap();
            gl.fog(FogParam::Start(0.0)).unwrap();
            gl.fog(FogParam::End(10.0)).unwrap();
            gl.fog(FogParam::Color([0.0, 0.0, 0.0, 0.0])).unwrap();
            gl.fog(FogParam::CoordSrc(FogCoordSrc::FogCoord)).unwrap();
            gl.fog_coord(7.5);
            gl.color4(1.0, 1.0, 1.0, 0.5);
            gl.window_pos(1.0, 1.0, 0.0).unwrap();
            let img = [255u8, 255, 255, 128].repeat(4);
            gl.draw_pixels(2, 2, DrawKind::Color, &rgba(&img)).unwrap();
            let b = BitmapImage::unpack(2, 1, &[0b1100_0000], &PixelStore::DEFAULT).unwrap();
            gl.window_pos(4.0, 1.0, 0.0).unwrap();
            gl.bitmap(&b, [0.0, 0.0], [0.0, 0.0]).unwrap();
            gl.disable(Capability::Fog).unwrap();
            gl.enable(Capability::ColorSum).unwrap();
            gl.secondary_color3(0.25, 0.0, 0.0);
            gl.color4(0.0, 0.0, 0.0, 1.0);
            gl.window_pos(7.0, 1.0, 0.0).unwrap();
            let black = [0u8, 0, 0, 255].repeat(4);
            gl.draw_pixels(2, 2, DrawKind::Color, &rgba(&black)).unwrap();
            gl.window_pos(10.0, 1.0, 0.0).unwrap();
            gl.bitmap(&b, [0.0, 0.0], [0.0, 0.0]).unwrap();
            let fb = gl.framebuffer();
            assert_eq!(fb.pixel(1, 1), Some([64, 64, 64, 128]), "{backend:?}");
            assert_eq!(fb.pixel(4, 1), Some([64, 64, 64, 128]), "{backend:?}");
            assert_eq!(fb.pixel(7, 1), Some([64, 0, 0, 255]), "{backend:?}");
            assert_eq!(fb.pixel(10, 1), Some([64, 0, 0, 255]), "{backend:?}");
        }
    }
}
