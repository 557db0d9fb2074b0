//! The one boundary from compiled code back into Rust: [`texture_group`]
//! hands a group of four fragments' texture sampling to the reference
//! sampler (`crate::texture::sample_quad`), for the units the specialist does not
//! sample natively.
//!
//! Compiled code reaches the draw's textures only through a [`TexView`],
//! built by the specialist from the [`TextureSet`] at the call boundary and
//! valid for the whole call; everything in it is read-only.

use crate::texture::lod::LodState;
use crate::texture::{QuadSample, SamplerStatics, TexUnitKey, TextureRef, TextureSet, MAX_LEVELS, MAX_UNITS};
use std::marker::PhantomData;

/// The draw's textures as compiled code sees them. `#[repr(C)]`: the
/// generated code reads its fields at their `offset_of!` offsets.
#[repr(C, align(16))]
#[derive(Debug)]
pub struct TexView<'a> {
    /// `GL_TEXTURE_ENV_COLOR` of each unit, `env_color[u][channel]`
    /// repeated in four lanes so that one vector load splats it.
    pub env_color: [[[f32; 4]; 4]; MAX_UNITS],
    /// What generated code samples of the units it samples natively
    /// (`crate::compile::native_unit`); zero for the others.
    pub units: [UnitView; MAX_UNITS],
    /// The draw's [`TextureSet`], type-erased, for [`texture_group`].
    set: *const (),
    /// The texture units of the specialist's key, for [`texture_group`] and
    /// [`TexView::is_for`].
    keys: [Option<TexUnitKey>; MAX_UNITS],
    _borrow: PhantomData<&'a TextureSet<'a>>,
}

/// One natively sampled unit: the values `crate::texture::sample_quad`
/// derives from its `TextureRef`, each repeated in four lanes (masks as all
/// ones or zero), and its levels.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug)]
pub struct UnitView {
    /// The base level's width and height as floats (λ is measured in its texels).
    pub base_size: [[f32; 4]; 2],
    /// `crate::texture::lod::LodState`'s values (its flags are the key's
    /// `SamplerStatics`).
    pub min_lod: [f32; 4],
    pub max_lod: [f32; 4],
    pub bias: [f32; 4],
    /// The first and last level sampled (`base_level`, `max(max_level, base_level)`).
    pub first: [i32; 4],
    pub last: [i32; 4],
    /// The first level's width and height: level `l`'s are
    /// `max(1, side >> (l − first))` (checked by `UnitView::new`).
    pub base_side: [[i32; 4]; 2],
    /// Levels `first..=last` (the others zero): every one non-empty, at
    /// least 1×1, and holding `4 · width · height` bytes (texels, or
    /// depth-test units: `crate::texture::DepthUnits`).
    pub levels: [LevelView; MAX_LEVELS],
}

/// One level of a natively sampled unit.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct LevelView {
    pub texels: *const u8,
    pub width: i32,
    pub height: i32,
}

impl Default for UnitView {
    fn default() -> UnitView {
        UnitView {
            base_size: [[0.0; 4]; 2],
            min_lod: [0.0; 4],
            max_lod: [0.0; 4],
            bias: [0.0; 4],
            first: [0; 4],
            last: [0; 4],
            base_side: [[0; 4]; 2],
            levels: [LevelView {
                texels: std::ptr::null(),
                width: 0,
                height: 0,
            }; MAX_LEVELS],
        }
    }
}

/// Largest level side the native path takes (its texel offsets stay below 2^31).
const NATIVE_MAX_SIDE: u32 = 16384;

impl UnitView {
    /// The view of `tex` for native sampling with `key`, or `None` when a
    /// level it may read is missing or malformed (the reference reads zeros
    /// there) or the key's statics are not the texture's: the specialist
    /// then leaves the whole call to the interpreter.
    fn new(key: &TexUnitKey, tex: &TextureRef<'_>) -> Option<UnitView> {
        if key.sampler.statics != SamplerStatics::of(&key.sampler, tex) {
            return None;
        }
        let first = tex.base_level;
        let last = tex.max_level.max(first);
        let image = |l: u32| tex.images.get(l as usize).filter(|im| !im.texels.is_empty());
        let base = image(first)?;
        let mut v = UnitView::default();
        for l in first..=last {
            let im = image(l)?;
            // The sizes of a mipmap chain (GL's completeness asks for them).
            let chained = |side: u32, base: u32| side == (base >> (l - first).min(31)).max(1);
            let ok = (1..=NATIVE_MAX_SIDE).contains(&im.width)
                && (1..=NATIVE_MAX_SIDE).contains(&im.height)
                && chained(im.width, base.width)
                && chained(im.height, base.height)
                && match im.units {
                    Some(u) => u.z.len() >= im.width as usize * im.height as usize,
                    None => im.texels.len() >= 4 * im.width as usize * im.height as usize,
                };
            if !ok {
                return None;
            }
            // Depth-test units are read as the texels (`f32` bits for float
            // depth; 24-bit units converted per lookup: `statics.depth_units`).
            let texels = match im.units {
                Some(u) => u.z.as_ptr().cast::<u8>(),
                None => im.texels.as_ptr(),
            };
            *v.levels.get_mut(l as usize)? = LevelView {
                texels,
                width: im.width as i32,
                height: im.height as i32,
            };
        }
        let s = LodState::new(&key.sampler, tex);
        v.base_size = [[base.width as f32; 4], [base.height as f32; 4]];
        v.min_lod = [s.min_lod; 4];
        v.max_lod = [s.max_lod; 4];
        v.bias = [s.bias; 4];
        v.first = [first as i32; 4];
        v.last = [last as i32; 4];
        v.base_side = [[base.width as i32; 4], [base.height as i32; 4]];
        Some(v)
    }
}

impl<'a> TexView<'a> {
    /// The view of `set` for a specialist of a key with texture units
    /// `keys`, or `None` when a natively sampled unit has no texture or one
    /// the native path cannot read (`UnitView::new`).
    pub fn new(keys: &'a [Option<TexUnitKey>; MAX_UNITS], set: &'a TextureSet<'a>) -> Option<TexView<'a>> {
        let mut units = [UnitView::default(); MAX_UNITS];
        for ((key, tex), view) in keys.iter().zip(&set.units).zip(&mut units) {
            if let Some(key) = key.as_ref().filter(|k| crate::compile::native_unit(k)) {
                *view = UnitView::new(key, tex.as_ref()?)?;
            }
        }
        Some(TexView {
            env_color: set.env_color.map(|c| c.map(|v| [v; 4])),
            units,
            set: (set as *const TextureSet<'a>).cast(),
            keys: *keys,
            _borrow: PhantomData,
        })
    }
}

impl TexView<'_> {
    /// Whether this is the view of a key with texture units `units` (what
    /// that key's generated code may read of it).
    pub fn is_for(&self, units: &[Option<TexUnitKey>; MAX_UNITS]) -> bool {
        self.keys == *units
    }
}

/// What compiled code hands [`texture_group`] for one group of four lanes:
/// the units to sample, the lanes' pixels and each unit's coordinates at
/// the pixels of the lanes' quads (what the interpreter computes from the
/// planes, `crate::shade::sample_unit`); the samples come back in
/// `samples`.
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug)]
pub struct TexCall {
    /// The lanes' pixel columns and their row, in llvmpipe's top-down frame
    /// (`interp::row_of`), as the specialist evaluates the planes at them.
    pub px: [f32; 4],
    pub row: [f32; 4],
    /// `samples[u][channel][lane]`: unit `u`'s filtered RGBA, for the units
    /// of `units` and the lanes of `live` (the rest is left as it is).
    pub samples: [[[f32; 4]; 4]; MAX_UNITS],
    /// `coords[u][k][c][i]`: unit `u`'s coordinate `c` (s, t, r, q before
    /// projection: `crate::shade::tex_coords`) at pixel `k` (top-left,
    /// top-right, bottom-left, bottom-right: `crate::shade::quad_coords`)
    /// of lane `i`'s quad, for the units of `units`.
    pub coords: [[[[f32; 4]; 4]; 4]; MAX_UNITS],
    /// The [`TexView`] of the call (`SpanCall::tex`).
    pub view: *const TexView<'static>,
    /// Bit `i`: lane `i` is live.
    pub live: u32,
    /// Bit `u`: sample unit `u`.
    pub units: u32,
}

/// The samples of a group: for each unit of `call.units` the key enables
/// and each live lane, the reference sampler at the lane's quad
/// (`crate::shade::sample_unit`), or 0 when the set has no texture for the
/// unit (as `crate::shade::texture` leaves it). Does nothing when `call`
/// or its view is null.
///
/// # Safety
/// `call` is null or points to a `TexCall` that nothing else accesses during
/// the call, whose `view` is null or the `TexView` the specialist built for
/// the running call (its referents outlive the call).
pub unsafe extern "C" fn texture_group(call: *mut TexCall) {
    // SAFETY: by the contract above `call` is null or a valid, exclusive
    // `TexCall` (a stack slot of the calling group).
    let Some(call) = (unsafe { call.as_mut() }) else {
        return;
    };
    // SAFETY: `view` is null or the `TexView` `Specialist::run_splatted`
    // built for this call, alive until it returns.
    let Some(view) = (unsafe { call.view.as_ref() }) else {
        return;
    };
    // SAFETY: `TexView::new` made `set` from a reference that outlives the
    // view (its `'a`) to a `TextureSet`.
    let set = unsafe { &*view.set.cast::<TextureSet<'_>>() };
    for (u, (key, tex)) in view.keys.iter().zip(&set.units).enumerate() {
        let Some(key) = key.as_ref().filter(|_| call.units & (1 << u) != 0) else {
            continue;
        };
        // The lanes of a group are two quads' pixels: a quad's projection, λ
        // and the filter's set-up (`crate::texture::QuadSample`, the same
        // bits as `sample_quad`) are made once for its lanes, not once per
        // lane. MuJoCo's shadowed frame (texgen'd shadow-map lookups, then
        // through here; osmesa/bench/mujoco_frame.py, 320x240, 1 thread,
        // loaded machine): ~1550 to ~1000 ms, `mujoco.sh` s1/l1 3.3x to 2.0x.
        let Some(tex) = tex.as_ref() else {
            for lane in (0..4).filter(|l| call.live & (1 << l) != 0) {
                for channel in &mut call.samples[u] {
                    channel[lane] = 0.0;
                }
            }
            continue;
        };
        // The generated code evaluated the coordinates at the pixels of each
        // lane's quad with the instruction (`compile::texture`), the same
        // values as `quad_coords` here, whose fused multiply-adds are libm
        // calls (`f32::mul_add` without the target feature: a quad's 20
        // `Planes::at` took ~600 instructions). The sRGB light pass of
        // `osmesa/bench/shadow_lookup.c` (320×240, 4×, its checker as sRGB;
        // callgrind): 4169 to 3739 instructions a sample.
        let coords = &call.coords[u];
        let mut cached: Option<((u32, u32), QuadSample<'_>)> = None;
        for lane in (0..4).filter(|l| call.live & (1 << l) != 0) {
            let (origin, l) = crate::shade::quad_lane((call.px[lane], call.row[lane]));
            let bits = (origin.0.to_bits(), origin.1.to_bits());
            if cached.as_ref().map(|c| c.0) != Some(bits) {
                let quad = std::array::from_fn(|k| std::array::from_fn(|c| coords[k][c][lane]));
                cached = Some((bits, QuadSample::new(key, tex, &quad)));
            }
            let texel = cached.as_ref().map_or([0.0; 4], |(_, q)| q.lane(l));
            for (c, v) in texel.into_iter().enumerate() {
                call.samples[u][c][lane] = v;
            }
        }
    }
}
