//! The texture objects of a context, the default texture of each target,
//! the proxy images, and which object each unit has bound to each target.

use super::jit::{
    quantized_lod_bias, BaseFormat, Image, MipFilter, SamplerKey, SamplerStatics, TexTarget, TextureRef, Wrap,
    MAX_UNITS,
};
use super::object::{ImageUnits, TextureObject};
use crate::names::Names;
use std::sync::Arc;

const TARGETS: [TexTarget; 5] = [
    TexTarget::D1,
    TexTarget::D2,
    TexTarget::D3,
    TexTarget::Cube,
    TexTarget::Rect,
];

fn index(target: TexTarget) -> usize {
    match target {
        TexTarget::D1 => 0,
        TexTarget::D2 => 1,
        TexTarget::D3 => 2,
        TexTarget::Cube => 3,
        TexTarget::Rect => 4,
    }
}

/// Every texture object of a context and the bindings of its units.
#[derive(Clone, Debug)]
pub struct TextureStore {
    named: Names<TextureObject>,
    defaults: [TextureObject; 5],
    /// Proxy images: sizes and formats only, no texels.
    pub(crate) proxies: [TextureObject; 5],
    bindings: [[u32; 5]; MAX_UNITS],
    active: usize,
    /// The samplers read depth kept as units ([`super::TexImage::units`])
    /// in place; off (a switch for tests comparing the two), they read the
    /// texels written from them when the framebuffer object releases them.
    pub(crate) sample_units: bool,
}

impl Default for TextureStore {
    fn default() -> Self {
        TextureStore::new()
    }
}

impl TextureStore {
    pub fn new() -> TextureStore {
        TextureStore {
            named: Names::new(),
            defaults: TARGETS.map(TextureObject::new),
            proxies: TARGETS.map(TextureObject::new),
            bindings: [[0; 5]; MAX_UNITS],
            active: 0,
            sample_units: true,
        }
    }

    /// The active texture unit (`glActiveTexture`).
    pub fn active_unit(&self) -> usize {
        self.active
    }

    pub(crate) fn set_active_unit(&mut self, unit: usize) {
        self.active = unit.min(MAX_UNITS - 1);
    }

    /// `n` new names (`glGenTextures`), reserved but without objects until
    /// bound (`None`: none left, [`Names::gen`]).
    pub(crate) fn gen(&mut self, n: usize) -> Option<Vec<u32>> {
        self.named.gen(n)
    }

    /// Binds `name` to `target` on the active unit, creating its object on
    /// first bind; `false` when the object exists with another target.
    pub(crate) fn bind(&mut self, target: TexTarget, name: u32) -> bool {
        if name != 0 {
            let slot = self.named.slot(name);
            match slot {
                Some(obj) if obj.target != target => return false,
                Some(_) => {}
                None => *slot = Some(TextureObject::new(target)),
            }
        }
        self.bindings[self.active][index(target)] = name;
        true
    }

    /// Deletes named objects, unbinding them from every unit (they revert to 0).
    pub(crate) fn delete(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 || !self.named.remove(name) {
                continue;
            }
            for unit in &mut self.bindings {
                for b in unit.iter_mut().filter(|b| **b == name) {
                    *b = 0;
                }
            }
        }
    }

    /// Whether `name` names an object (generated names count once bound).
    pub fn is_texture(&self, name: u32) -> bool {
        self.named.get(name).is_some()
    }

    /// Whether `name` was generated or bound (`glAreTexturesResident` and
    /// `glPrioritizeTextures` accept exactly these).
    pub(crate) fn exists(&self, name: u32) -> bool {
        self.named.is_reserved(name)
    }

    /// The object `name` (`None` for a name without an object).
    pub fn object(&self, name: u32) -> Option<&TextureObject> {
        self.named.get(name)
    }

    pub(crate) fn object_mut(&mut self, name: u32) -> Option<&mut TextureObject> {
        self.named.get_mut(name)
    }

    /// The name bound to `target` on `unit`.
    pub fn binding(&self, unit: usize, target: TexTarget) -> u32 {
        self.bindings.get(unit).map_or(0, |b| b[index(target)])
    }

    /// The object bound to `target` on `unit` (the default texture for 0).
    pub fn bound(&self, unit: usize, target: TexTarget) -> &TextureObject {
        let name = self.binding(unit, target);
        self.object(name).unwrap_or(&self.defaults[index(target)])
    }

    /// The object bound to `target` on the active unit.
    pub(crate) fn current_mut(&mut self, target: TexTarget) -> &mut TextureObject {
        let name = self.binding(self.active, target);
        match self.named.get_mut(name) {
            Some(obj) => obj,
            None => &mut self.defaults[index(target)],
        }
    }

    pub(crate) fn proxy(&self, target: TexTarget) -> &TextureObject {
        &self.proxies[index(target)]
    }

    pub(crate) fn proxy_mut(&mut self, target: TexTarget) -> &mut TextureObject {
        &mut self.proxies[index(target)]
    }

    /// What the draw needs of `target` on `unit`: `None` when the bound
    /// texture is incomplete.
    pub fn sampling(&self, unit: usize, target: TexTarget) -> Option<Sampling<'_>> {
        let obj = self.bound(unit, target);
        let last = obj.complete()?;
        // Without mipmapping only the base level is sampled (and the others need not be complete).
        let last = if obj.params.mip == MipFilter::None {
            obj.params.base_level as usize
        } else {
            last
        };
        let base = obj.base_image()?;
        let p = &obj.params;
        let storage = base.internal.storage();
        let wrap = match target {
            TexTarget::D1 => [p.wrap[0], Wrap::Repeat, Wrap::Repeat],
            TexTarget::D2 | TexTarget::Cube | TexTarget::Rect => [p.wrap[0], p.wrap[1], Wrap::Repeat],
            TexTarget::D3 => p.wrap,
        };
        let key = SamplerKey {
            target,
            format: storage.texel_format(),
            min: p.min,
            mip: p.mip,
            mag: p.mag,
            wrap,
            compare: (p.compare && storage.base == BaseFormat::Depth).then_some(p.compare_func),
            depth_mode: p.depth_mode,
            // The unit's plan adds them, with the unit's LOD bias.
            statics: SamplerStatics::default(),
        };
        let faces = obj.faces();
        let levels = &obj.images[..(last + 1) * faces];
        let images = levels
            .iter()
            .map(|i| match i {
                Some(i) => Image {
                    texels: &i.texels,
                    units: i.units.as_ref().filter(|_| self.sample_units).map(ImageUnits::view),
                    width: i.width,
                    height: i.height,
                    depth: i.depth,
                },
                None => Image::EMPTY,
            })
            .collect();
        Some(Sampling {
            key,
            base: storage.base,
            images,
            shared: levels
                .iter()
                .map(|i| {
                    i.as_ref().map(|i| {
                        let units = i.units.clone().filter(|_| self.sample_units);
                        (Arc::clone(&i.texels), units)
                    })
                })
                .collect(),
            params: TextureRef {
                images: &[],
                base_level: p.base_level as u32,
                max_level: last as u32,
                // As gallium's sampler state holds them (`main/texparam.c`): no negative minimum.
                min_lod: p.min_lod.max(0.0),
                max_lod: p.max_lod,
                lod_bias: quantized_lod_bias(p.lod_bias),
                border: border_for_base(p.border, storage.base),
                float_depth: storage.float,
            },
        })
    }
}

/// The border colour as the sampler sees it for a base format (Mesa
/// `state_tracker/st_format.c` `st_translate_color`).
pub fn border_for_base(c: [f32; 4], base: BaseFormat) -> [f32; 4] {
    match base {
        BaseFormat::Alpha => [0.0, 0.0, 0.0, c[3]],
        BaseFormat::Luminance => [c[0], c[0], c[0], 1.0],
        BaseFormat::LuminanceAlpha => [c[0], c[0], c[0], c[3]],
        BaseFormat::Intensity => [c[0]; 4],
        BaseFormat::Rgb => [c[0], c[1], c[2], 1.0],
        BaseFormat::Rgba | BaseFormat::Depth => c,
    }
}

/// A complete unit's texture for one draw: the key parts and views of its texels.
#[derive(Clone, Debug)]
pub struct Sampling<'a> {
    pub key: SamplerKey,
    pub base: BaseFormat,
    /// Level `l`, face `f` at `l * faces + f`, up to the last level sampled; missing levels are empty.
    pub images: Vec<Image<'a>>,
    /// The texels (and depth units) behind `images` (`None` for empty
    /// ones), for [`Sampling::share`].
    shared: Vec<Option<SharedImage>>,
    /// The rest of the sampler's view: no images (they are [`Sampling::images`]),
    /// the object's LOD bias quantized ([`quantized_lod_bias`]).
    params: TextureRef<'static>,
}

/// An image's texels, shared with the texture object.
pub type SharedTexels = Arc<Vec<u8>>;

/// An image's texels and depth units ([`super::TexImage::units`]), shared
/// with the texture object.
type SharedImage = (SharedTexels, Option<ImageUnits>);

/// A [`Sampling`] that holds its texels (shared with the texture object,
/// which copies them before a later write): what a deferred draw keeps.
#[derive(Clone, Debug)]
pub struct SharedSampling {
    key: SamplerKey,
    base: BaseFormat,
    /// Each image's texels (`None`: empty), depth units and size.
    images: Vec<(Option<SharedImage>, [u32; 3])>,
    params: TextureRef<'static>,
}

impl SharedSampling {
    /// The texels held.
    pub fn texels(&self) -> impl Iterator<Item = &SharedTexels> {
        self.images.iter().filter_map(|(t, _)| t.as_ref().map(|(t, _)| t))
    }

    /// The sampling again, viewing the texels held.
    pub fn sampling(&self) -> Sampling<'_> {
        let images = self
            .images
            .iter()
            .map(|(t, [width, height, depth])| match t {
                Some((t, u)) => Image {
                    texels: t,
                    units: u.as_ref().map(ImageUnits::view),
                    width: *width,
                    height: *height,
                    depth: *depth,
                },
                None => Image::EMPTY,
            })
            .collect();
        Sampling {
            key: self.key,
            base: self.base,
            images,
            shared: self.images.iter().map(|(t, _)| t.clone()).collect(),
            params: self.params,
        }
    }
}

impl Sampling<'_> {
    /// The sampling with its texels held, for a draw that runs later.
    pub fn share(&self) -> SharedSampling {
        SharedSampling {
            key: self.key,
            base: self.base,
            images: self
                .shared
                .iter()
                .zip(&self.images)
                .map(|(t, i)| (t.clone(), [i.width, i.height, i.depth]))
                .collect(),
            params: self.params,
        }
    }

    /// The sampler's view, with the unit's LOD bias (`GL_TEXTURE_FILTER_CONTROL`,
    /// quantized by the caller with [`quantized_lod_bias`]) added.
    pub fn texture_ref(&self, unit_lod_bias: f32) -> TextureRef<'_> {
        TextureRef {
            images: &self.images,
            lod_bias: self.params.lod_bias + unit_lod_bias,
            ..self.params
        }
    }
}
