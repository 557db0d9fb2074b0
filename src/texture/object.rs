//! A texture object: its images (per level and face), its sampler
//! parameters, and GL's completeness rules (Mesa `main/texobj.c`
//! `_mesa_test_texture_completeness`).

use super::format::InternalFormat;
use super::jit::{BaseFormat, DepthMode, Filter, MipFilter, TexTarget, TexelFormat, Wrap};
use super::{faces, max_levels};
use softgl_jit::CompareFunc;
use std::sync::Arc;

/// One image: a level of a target, or one face of a cube map level. Texels
/// tightly packed in the internal format's [`TexelFormat`], rows bottom-up.
#[derive(Clone, Debug, PartialEq)]
pub struct TexImage {
    pub width: u32,
    pub height: u32,
    pub depth: u32,
    /// 0, except for proxy images (Mesa strips borders of real images at
    /// upload, llvmpipe keeps none, but records a proxy's as asked).
    pub border: u32,
    pub internal: InternalFormat,
    /// Shared with the draws deferred until the next flush, which read the
    /// texels as they were when drawn: writers copy them first when shared
    /// ([`TexImage::texels_mut`]).
    pub texels: Arc<Vec<u8>>,
    /// The depth texels as a framebuffer object rendered them (the depth
    /// test's units, see [`ImageUnits`]); `texels`' depth part is stale
    /// until [`ImageUnits::written`], its stencil plane never is. Readers of
    /// the depth texels other than the samplers materialise them first
    /// ([`TexImage::materialise`]: `Context::sync_texture`), writers drop
    /// them ([`TexImage::texels_mut`]).
    pub units: Option<ImageUnits>,
}

/// Depth texels kept in the depth test's units: the buffer a framebuffer
/// object rendered into a 2D depth image (24-bit or float depth), handed
/// to the image instead of written back as `Depth32F` texels, and read by
/// the samplers in place ([`softgl_jit::texture::DepthUnits`]). The
/// write-back was 64 MiB read and 64 MiB written per pass into a 4096²
/// shadow map, ~4.4 ms each, two a MuJoCo frame.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageUnits {
    /// One unit a texel, the image's size.
    pub z: Arc<Vec<u32>>,
    /// 24-bit unorm units, else float depth (`f32` bits).
    pub unorm24: bool,
    /// The texels hold them too ([`TexImage::materialise`]).
    pub written: bool,
}

impl ImageUnits {
    /// The sampler's view.
    pub fn view(&self) -> softgl_jit::texture::DepthUnits<'_> {
        softgl_jit::texture::DepthUnits {
            z: &self.z,
            unorm24: self.unorm24,
        }
    }

    /// Writes the units as `Depth32F` texels into `out` (4 bytes a unit),
    /// on two threads for big images.
    pub fn write_texels(&self, out: &mut [u8]) {
        let unorm24 = self.unorm24;
        // One loop a kind, for each to vectorize (`cvtdq2ps`).
        let run = |z: &[u32], out: &mut [u8]| {
            if unorm24 {
                for (o, &z) in out.chunks_exact_mut(4).zip(z) {
                    o.copy_from_slice(&softgl_jit::texture::DepthUnits::texel(z, true).to_ne_bytes());
                }
            } else {
                for (o, &z) in out.chunks_exact_mut(4).zip(z) {
                    o.copy_from_slice(&z.to_ne_bytes());
                }
            }
        };
        let n = self.z.len().min(out.len() / 4);
        let (z, out) = (&self.z[..n], &mut out[..4 * n]);
        if n < 1 << 20 {
            run(z, out);
            return;
        }
        let half = n / 2;
        let (za, zb) = z.split_at(half);
        let (oa, ob) = out.split_at_mut(4 * half);
        std::thread::scope(|s| {
            s.spawn(|| run(za, oa));
            run(zb, ob);
        });
    }
}

impl TexImage {
    /// An image of zeros (texels are undefined in GL until uploaded).
    pub fn new(internal: InternalFormat, size: [u32; 3]) -> TexImage {
        let n = size.iter().map(|&s| s as usize).product::<usize>();
        TexImage {
            width: size[0],
            height: size[1],
            depth: size[2],
            border: 0,
            internal,
            texels: Arc::new(vec![
                0;
                n * (internal.storage().texel_format().bytes_per_texel()
                    + internal.stencil_bits() as usize / 8)
            ]),
            units: None,
        }
    }

    /// The texels to write, copied first if a deferred draw still reads
    /// them; depth kept as units is materialised first, and dropped.
    pub fn texels_mut(&mut self) -> &mut Vec<u8> {
        self.materialise();
        self.units = None;
        Arc::make_mut(&mut self.texels)
    }

    /// The texels to write the stencil plane of (a packed depth-stencil
    /// image), leaving depth kept as units as it is.
    pub fn stencil_texels_mut(&mut self) -> &mut Vec<u8> {
        Arc::make_mut(&mut self.texels)
    }

    /// Depth kept as units ([`TexImage::units`]) written into the
    /// `Depth32F` texels, which hold it again (the units stay: they are
    /// what the framebuffer object that rendered them draws into next).
    pub fn materialise(&mut self) {
        let Some(u) = self.units.as_mut().filter(|u| !u.written) else {
            return;
        };
        u.written = true;
        let n = self.width as usize * self.height as usize * self.depth as usize;
        let t = Arc::make_mut(&mut self.texels);
        if let Some(out) = t.get_mut(..4 * n) {
            u.write_texels(out);
        }
    }

    pub fn texel_format(&self) -> TexelFormat {
        self.internal.storage().texel_format()
    }

    pub fn size(&self) -> [u32; 3] {
        [self.width, self.height, self.depth]
    }

    /// Byte offset of texel `(x, y, z)`.
    pub fn offset(&self, x: usize, y: usize, z: usize) -> usize {
        ((z * self.height as usize + y) * self.width as usize + x) * self.texel_format().bytes_per_texel()
    }

    /// Where texel `(x, y, z)`'s stencil byte is, for a packed depth-stencil
    /// image: a plane of bytes after the `Depth32F` texels (which the sampler
    /// reads as any depth texture's).
    pub fn stencil_offset(&self, x: usize, y: usize, z: usize) -> usize {
        let n = self.width as usize * self.height as usize * self.depth as usize;
        n * self.texel_format().bytes_per_texel() + (z * self.height as usize + y) * self.width as usize + x
    }
}

/// The sampler parameters of a texture object (`glTexParameter`), GL's initial values by default.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SamplerState {
    pub min: Filter,
    pub mip: MipFilter,
    pub mag: Filter,
    /// s, t, r.
    pub wrap: [Wrap; 3],
    /// Clamped to [0, 1] when set (Mesa's compatibility context lacks ARB_texture_float).
    pub border: [f32; 4],
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    pub priority: f32,
    pub generate_mipmap: bool,
    pub compare: bool,
    pub compare_func: CompareFunc,
    pub depth_mode: DepthMode,
}

impl SamplerState {
    /// A new object's parameters for `target`: GL's defaults, except that a
    /// rectangle texture starts with CLAMP_TO_EDGE and LINEAR minification
    /// (ARB_texture_rectangle issues 5 and 6; Mesa `_mesa_initialize_texture_object`).
    pub fn for_target(target: TexTarget) -> SamplerState {
        match target {
            TexTarget::Rect => SamplerState {
                min: Filter::Linear,
                mip: MipFilter::None,
                wrap: [Wrap::ClampToEdge; 3],
                ..SamplerState::default()
            },
            TexTarget::D1 | TexTarget::D2 | TexTarget::D3 | TexTarget::Cube => SamplerState::default(),
        }
    }
}

impl Default for SamplerState {
    fn default() -> Self {
        SamplerState {
            min: Filter::Nearest,
            mip: MipFilter::Linear,
            mag: Filter::Linear,
            wrap: [Wrap::Repeat; 3],
            border: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            priority: 1.0,
            generate_mipmap: false,
            compare: false,
            compare_func: CompareFunc::Lequal,
            depth_mode: DepthMode::Luminance,
        }
    }
}

/// A texture object (named, or a target's default texture 0).
#[derive(Clone, Debug, PartialEq)]
pub struct TextureObject {
    pub target: TexTarget,
    /// Level `l`, face `f` at `l * faces + f`.
    pub images: Vec<Option<TexImage>>,
    pub params: SamplerState,
}

impl TextureObject {
    pub fn new(target: TexTarget) -> TextureObject {
        TextureObject {
            target,
            images: vec![None; max_levels(target) * faces(target)],
            params: SamplerState::for_target(target),
        }
    }

    pub fn faces(&self) -> usize {
        faces(self.target)
    }

    pub fn image(&self, level: usize, face: usize) -> Option<&TexImage> {
        self.images.get(level * self.faces() + face)?.as_ref()
    }

    pub fn image_mut(&mut self, level: usize, face: usize) -> Option<&mut Option<TexImage>> {
        let faces = self.faces();
        self.images.get_mut(level * faces + face)
    }

    /// The image at the base level (face 0).
    pub fn base_image(&self) -> Option<&TexImage> {
        usize::try_from(self.params.base_level)
            .ok()
            .and_then(|b| self.image(b, 0))
    }

    /// The last level the chain from the base level can reach:
    /// `min(MAX_LEVEL, base + log2(largest side), levels − 1)` (Mesa's `_MaxLevel`).
    pub fn last_level(&self) -> Option<usize> {
        let base = usize::try_from(self.params.base_level).ok()?;
        let img = self.base_image()?;
        let side = match self.target {
            TexTarget::D1 => img.width,
            TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => img.width.max(img.height),
            TexTarget::D3 => img.width.max(img.height).max(img.depth),
        };
        let log2 = side.max(1).ilog2() as usize;
        let max_level = usize::try_from(self.params.max_level).ok()?;
        Some(max_level.min(base + log2).min(max_levels(self.target) - 1))
    }

    /// Whether the texture can be sampled with its own parameters; the last
    /// level sampled when it can.
    pub fn complete(&self) -> Option<usize> {
        let base = usize::try_from(self.params.base_level).ok()?;
        if base >= max_levels(self.target) || self.params.max_level < self.params.base_level {
            return None;
        }
        let img = self.base_image()?;
        if img.width == 0 || img.height == 0 || img.depth == 0 {
            return None;
        }
        let last = self.last_level()?;
        let same = |i: &TexImage, size: [u32; 3]| i.internal == img.internal && i.size() == size;
        if (1..self.faces()).any(|f| !self.image(base, f).is_some_and(|i| same(i, img.size()))) {
            return None;
        }
        if self.params.mip != MipFilter::None {
            let mut size = img.size();
            for level in base + 1..=last {
                size = next_size(self.target, size);
                if (0..self.faces()).any(|f| !self.image(level, f).is_some_and(|i| same(i, size))) {
                    return None;
                }
            }
        }
        Some(last)
    }

    /// The base format of the base image (Rgba for a texture without one).
    pub fn base_format(&self) -> BaseFormat {
        self.base_image().map_or(BaseFormat::Rgba, |i| i.internal.base())
    }
}

/// The size of the next mipmap level: each side halved (rounding down) down to 1;
/// 1D keeps height and depth 1, 2D and cube maps keep depth 1.
pub fn next_size(target: TexTarget, size: [u32; 3]) -> [u32; 3] {
    let half = |s: u32| (s / 2).max(1);
    match target {
        TexTarget::D1 => [half(size[0]), 1, 1],
        TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => [half(size[0]), half(size[1]), 1],
        TexTarget::D3 => [half(size[0]), half(size[1]), half(size[2])],
    }
}
