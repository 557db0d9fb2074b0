//! Mipmap generation (`glGenerateMipmap`, `GL_GENERATE_MIPMAP`) as Mesa
//! 22.3.6 does it on llvmpipe: `st_generate_mipmap` → `util_gen_mipmap`,
//! which blits each level from the one above with a LINEAR, CLAMP_TO_EDGE
//! sampler (`gallium/auxiliary/util/u_gen_mipmap.c`). The blit draws a quad
//! whose texture coordinate at destination texel `i` is `(i + 0.5) / dst`,
//! so every size (odd ones included) is a bilinear (3D: trilinear) sample,
//! not a box filter. llvmpipe samples unorm8 formats on its 8-bit AoS path
//! (`gallivm/lp_bld_sample_aos.c`: 8 fractional bits, `pmulhrsw` lerps) and
//! others in f32; `docs/llvmpipe-facts.md` §18 lists what was checked
//! against Mesa's levels.

use super::format::{float_to_unorm, unorm_to_float, unorm_to_unorm, Storage};
use super::jit::TexelFormat;
use super::object::{next_size, TexImage, TextureObject};
use super::unpack::put_texel;
use softgl_jit::texture::arith::{lerp, lerp8, srgb8_to_linear, unorm16_to_float, unorm8_to_float};

/// Rebuilds, for each face in `faces`, the levels below the base level down
/// to the last level the chain reaches (Mesa's `_mesa_compute_num_levels`),
/// each from the level above.
pub fn generate(obj: &mut TextureObject, faces: std::ops::Range<usize>) {
    let Ok(base) = usize::try_from(obj.params.base_level) else {
        return;
    };
    let Some(last) = obj.last_level() else { return };
    for face in faces {
        for level in base + 1..=last {
            // An empty level (a 3D image of depth 0) has nothing to filter.
            let Some(src) = obj.image(level - 1, face).filter(|s| !s.size().contains(&0)) else {
                break;
            };
            let dst = downsample(src, next_size(obj.target, src.size()));
            if let Some(slot) = obj.image_mut(level, face) {
                *slot = Some(dst);
            }
        }
    }
}

/// The AoS path's neighbours and 8-bit weight for destination texel `i` of
/// `dst` from a source of `src` texels: `iround(s · src · 256) − 128`, its
/// integer part (clamped to the edge) and low 8 bits.
fn aos_coord(i: usize, dst: u32, src: u32) -> (usize, usize, u8) {
    let s = (i as f32 + 0.5) / dst as f32;
    let fixed = (s * (src * 256) as f32).round_ties_even() as i32 - 128;
    let last = src as i32 - 1;
    let i0 = fixed >> 8;
    (
        i0.clamp(0, last) as usize,
        (i0 + 1).clamp(0, last) as usize,
        (fixed & 255) as u8,
    )
}

/// The source coordinates of destination texel `p` in each dimension, by
/// `coord` ([`aos_coord`] or [`float_coord`]).
fn coords<T>(coord: fn(usize, u32, u32) -> T, p: [usize; 3], dst: [u32; 3], src: [u32; 3]) -> [T; 3] {
    let [d, s] = [dst, src];
    [0, 1, 2].map(|k| coord(p[k], d[k], s[k]))
}

/// The f32 path's neighbours and weight: `u = s · src − 0.5`.
fn float_coord(i: usize, dst: u32, src: u32) -> (usize, usize, f32) {
    let s = (i as f32 + 0.5) / dst as f32;
    let u = s * src as f32 - 0.5;
    let i0 = u.floor();
    let last = src as i32 - 1;
    let i0i = i0 as i32;
    (i0i.clamp(0, last) as usize, (i0i + 1).clamp(0, last) as usize, u - i0)
}

/// Linear to an sRGB byte with the exact curve (llvmpipe approximates it
/// with `rsqrtps`, whose bits are the CPU's: up to 1 apart, §18).
pub fn linear_to_srgb(l: f32) -> u32 {
    let l = l.clamp(0.0, 1.0);
    let s = if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0).round_ties_even() as u32
}

/// What a level's texel holds, per storage channel, on the path llvmpipe
/// samples it (the reference sampler's arithmetic, `softgl_jit::texture::arith`).
enum Texels {
    /// Bytes as stored (unorm8 formats of at most 8 bits: AoS).
    Bytes(Vec<[u8; 4]>),
    Floats(Vec<[f32; 4]>),
}

fn read(src: &TexImage, storage: &Storage) -> Texels {
    let t = &src.texels;
    // Texels only: a depth-stencil image's stencil plane follows them.
    let n = src.width as usize * src.height as usize * src.depth as usize;
    match storage.texel_format() {
        TexelFormat::Rgba8 => Texels::Bytes((0..n).map(|i| [0, 1, 2, 3].map(|c| t[4 * i + c])).collect()),
        TexelFormat::Srgba8 => Texels::Floats(
            (0..n)
                .map(|i| {
                    [0, 1, 2, 3].map(|c| {
                        let v = t[4 * i + c];
                        if c == 3 {
                            unorm8_to_float(v)
                        } else {
                            srgb8_to_linear(v)
                        }
                    })
                })
                .collect(),
        ),
        TexelFormat::Rgba16 => Texels::Floats(
            (0..n)
                .map(|i| {
                    [0, 1, 2, 3].map(|c| {
                        let v = u32::from(u16::from_ne_bytes([t[8 * i + 2 * c], t[8 * i + 2 * c + 1]]));
                        match storage.bits[c] {
                            0 | 16 => unorm16_to_float(v as u16),
                            b => unorm_to_float(unorm_to_unorm(v, 16, b), b),
                        }
                    })
                })
                .collect(),
        ),
        TexelFormat::Depth32F => Texels::Floats(
            t.chunks_exact(4)
                .map(|b| [f32::from_ne_bytes([b[0], b[1], b[2], b[3]]), 0.0, 0.0, 1.0])
                .collect(),
        ),
    }
}

/// An 8-bit AoS result requantized to a narrower channel as llvmpipe's
/// render target stores it: 4 bits round to nearest, 5 bits and fewer
/// truncate (measured, §18).
fn requantize(v: u32, bits: u32) -> u32 {
    match bits {
        8.. => v,
        4 => unorm_to_unorm(v, 8, 4),
        b => v >> (8 - b),
    }
}

/// Neighbours and weight along one axis.
type Axis<W> = (usize, usize, W);

/// Channel `c` of the trilinear sample at `a` (x, then y, then z, as
/// llvmpipe's `lp_build_lerp_3d`) with `lerp`.
fn trilinear<T: Copy, W: Copy>(
    v: &[[T; 4]],
    sw: usize,
    sh: usize,
    c: usize,
    a: [Axis<W>; 3],
    lerp: fn(W, T, T) -> T,
) -> T {
    let [(x0, x1, fx), (y0, y1, fy), (z0, z1, fz)] = a;
    let p = |x: usize, y: usize, z: usize| v[(z * sh + y) * sw + x][c];
    let plane = |z| {
        lerp(
            fy,
            lerp(fx, p(x0, y0, z), p(x1, y0, z)),
            lerp(fx, p(x0, y1, z), p(x1, y1, z)),
        )
    };
    lerp(fz, plane(z0), plane(z1))
}

/// `src` blitted down to `size`.
fn downsample(src: &TexImage, size: [u32; 3]) -> TexImage {
    let mut dst = TexImage::new(src.internal, size);
    let storage = src.internal.storage();
    let texels = read(src, &storage);
    let [sw, sh, sd] = src.size();
    for z in 0..size[2] as usize {
        for y in 0..size[1] as usize {
            for x in 0..size[0] as usize {
                let n: [u32; 4] = match &texels {
                    Texels::Bytes(v) => {
                        let a = coords(aos_coord, [x, y, z], size, [sw, sh, sd]);
                        std::array::from_fn(|c| {
                            let t = trilinear(v, sw as usize, sh as usize, c, a, lerp8);
                            requantize(u32::from(t), storage.bits[c])
                        })
                    }
                    Texels::Floats(v) => {
                        let a = coords(float_coord, [x, y, z], size, [sw, sh, sd]);
                        std::array::from_fn(|c| {
                            let f = trilinear(v, sw as usize, sh as usize, c, a, lerp);
                            match (storage.texel_format(), storage.bits[c]) {
                                (_, 0) => 0,
                                (TexelFormat::Srgba8, _) if c < 3 => linear_to_srgb(f),
                                (_, b) => float_to_unorm(f, b),
                            }
                        })
                    }
                };
                let at = dst.offset(x, y, z);
                put_texel(&mut dst.texels_mut()[at..], &storage, n);
            }
        }
    }
    dst
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aos_weights_of_a_two_to_one_reduction_are_halves() {
        // 4 → 2: texel 0 samples between source texels 0 and 1 at weight 128.
        assert_eq!(aos_coord(0, 2, 4), (0, 1, 128));
        assert_eq!(aos_coord(1, 2, 4), (2, 3, 128));
        // 5 → 2: s = 0.25, 0.25 · 1280 − 128 = 192: texels 0 and 1 at 192/256.
        assert_eq!(aos_coord(0, 2, 5), (0, 1, 192));
        // 1 → 1 clamps both neighbours to texel 0.
        assert_eq!(aos_coord(0, 1, 1), (0, 0, 0));
    }

    #[test]
    fn srgb_encode_ends_at_0_and_255() {
        assert_eq!(linear_to_srgb(1.0), 255);
        assert_eq!(linear_to_srgb(0.0), 0);
    }
}
