//! Texturing (GL 1.5 §3.8, §3.13 texture environments; issue 12): a
//! checkerboard receding plane under each minification filter, magnified
//! NEAREST and LINEAR, each wrap mode with a border colour, each environment
//! mode over lit spheres of every base format, multitexture with COMBINE
//! (every function, the `GL_TEXTUREn` crossbar) and DOT3 bump mapping, 1D,
//! 3D and cube maps, sphere-map texgen, a shadow map by depth compare, the
//! pyramid `gluBuild2DMipmaps` makes of a non-power-of-two image, and the
//! stiff cases (1x1 and 4096x1 textures, coordinates ±1e6, LOD bias ±100,
//! derivatives 0 and 1e30).
//!
//! Texture names are fixed per scene (GL makes an object at its first bind),
//! so a frame replayed on the same context binds the same objects again.

use super::glu::{self, Level};
use super::lighting::{light, lit_view, material, sphere_with, SphereTex};
use super::{panels, Group, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{
    Capability, CombineFn, CombineSrc, CompareFunc, DepthMode, EnvMode, Filter, InternalFormat, MatrixMode, MipFilter,
    Operand, PixelFormat, PixelType, PrimitiveMode, TexCoordName, TexEnvParam, TexGenMode, TexGenParam, TexImageTarget,
    TexParam, TextureTarget, Wrap,
};

const G: Group = Group::Texture;
/// Minification filters (`GL_TEXTURE_MIN_FILTER`).
const NEAREST: (Filter, MipFilter) = (Filter::Nearest, MipFilter::None);
const LINEAR: (Filter, MipFilter) = (Filter::Linear, MipFilter::None);
const TRILINEAR: (Filter, MipFilter) = (Filter::Linear, MipFilter::Linear);
const T2: TextureTarget = TextureTarget::D2;

/// Measured 2026-11-23 (scenes branch with store, pipe and sample merged;
/// the NEAREST, wrap, 1D, shadow, mipmap and stiff scenes since glFrustum/glOrtho
/// are built in f32 and the viewport transform is fused as Mesa's, §11):
/// identical to llvmpipe at 96x96 and 256x256, softgl's interpreter and JIT alike.
const E: Tolerance = Tolerance {
    reason: "softgl samples and combines as llvmpipe's gallivm does (docs/llvmpipe-facts.md §16, §17): \
             identical at both sizes",
    ..Tolerance::EXACT
};

/// Measured 2026-11-23 (after the f32 projection matrices and fused viewport
/// transform, §11): colours 1 LSB off llvmpipe's on `test` pixels at 96x96 and
/// `report` at 256x256, none further (softpipe: thousands).
const fn lsb(test: usize, report: usize) -> Tolerance {
    Tolerance::lsb(
        test,
        report,
        "1 LSB on the pixels counted, from the interpolated colour or coordinate's last f32 bit \
         (docs/llvmpipe-facts.md 11); softpipe is off on 10-100x as many",
    )
}

pub fn scenes() -> Vec<Scene> {
    use Filter::{Linear as L, Nearest as N};
    let mins: [(&'static str, Filter, MipFilter, Tolerance); 6] = [
        ("tex_min_nearest", N, MipFilter::None, E),
        ("tex_min_linear", L, MipFilter::None, E),
        ("tex_min_nearest_mipmap_nearest", N, MipFilter::Nearest, E),
        ("tex_min_linear_mipmap_nearest", L, MipFilter::Nearest, E),
        ("tex_min_nearest_mipmap_linear", N, MipFilter::Linear, E),
        ("tex_min_linear_mipmap_linear", L, MipFilter::Linear, E),
    ];
    let mut v: Vec<Scene> = mins
        .into_iter()
        .map(|(name, f, m, t)| Scene::new(name, G, t, min_scene(f, m)))
        .collect();
    v.extend([
        Scene::new("tex_mag_nearest", G, E, |r, s| magnified(r, s, N)),
        Scene::new("tex_mag_linear", G, E, |r, s| magnified(r, s, L)),
        Scene::new("tex_wrap_repeat", G, E, |r, s| wrapped(r, s, Wrap::Repeat)),
        Scene::new("tex_wrap_clamp", G, E, |r, s| wrapped(r, s, Wrap::Clamp)),
        Scene::new("tex_wrap_clamp_to_edge", G, E, |r, s| wrapped(r, s, Wrap::ClampToEdge)),
        Scene::new("tex_wrap_clamp_to_border", G, E, |r, s| {
            wrapped(r, s, Wrap::ClampToBorder)
        }),
        Scene::new("tex_wrap_mirrored_repeat", G, E, |r, s| {
            wrapped(r, s, Wrap::MirroredRepeat)
        }),
        Scene::new("tex_env_modulate", G, lsb(127, 1101), |r, s| {
            env_spheres(r, s, EnvMode::Modulate)
        }),
        Scene::new("tex_env_replace", G, lsb(103, 954), |r, s| {
            env_spheres(r, s, EnvMode::Replace)
        }),
        Scene::new("tex_env_decal", G, lsb(336, 2569), |r, s| {
            env_spheres(r, s, EnvMode::Decal)
        }),
        Scene::new("tex_env_blend", G, lsb(123, 1105), |r, s| {
            env_spheres(r, s, EnvMode::Blend)
        }),
        Scene::new("tex_env_add", G, lsb(146, 1253), |r, s| env_spheres(r, s, EnvMode::Add)),
        Scene::new("tex_combine_functions", G, E, combine_functions),
        Scene::new("tex_combine_dot3_bump", G, E, dot3_bump),
        Scene::new("tex_1d", G, E, tex_1d),
        Scene::new("tex_3d", G, E, tex_3d),
        Scene::new("tex_cube_map", G, lsb(4, 42), cube_map),
        Scene::new("tex_texgen_sphere_map", G, lsb(1, 7), sphere_map),
        Scene::new("tex_shadow_map_compare", G, E, shadow_map),
        Scene::new("tex_build2dmipmaps_npot", G, E, npot_mipmaps),
        Scene::new("tex_1x1", G, E, one_by_one),
        Scene::new("tex_4096x1", G, E, wide),
        Scene::new("tex_coords_1e6", G, E, coords_1e6),
        Scene::new("tex_lod_bias_100", G, E, lod_bias),
        Scene::new("tex_derivatives_0_and_1e30", G, E, derivatives),
    ]);
    v
}

/// The minification scenes, one per filter (a `fn` pointer each).
fn min_scene(f: Filter, m: MipFilter) -> fn(&mut Rec, Size) {
    use Filter::{Linear as L, Nearest as N};
    match (f, m) {
        (N, MipFilter::None) => |r, s| receding_checker(r, s, (N, MipFilter::None)),
        (L, MipFilter::None) => |r, s| receding_checker(r, s, (L, MipFilter::None)),
        (N, MipFilter::Nearest) => |r, s| receding_checker(r, s, (N, MipFilter::Nearest)),
        (L, MipFilter::Nearest) => |r, s| receding_checker(r, s, (L, MipFilter::Nearest)),
        (N, MipFilter::Linear) => |r, s| receding_checker(r, s, (N, MipFilter::Linear)),
        (L, MipFilter::Linear) => |r, s| receding_checker(r, s, (L, MipFilter::Linear)),
    }
}

// ---------------------------------------------------------------- textures

/// An RGBA checker of `cell`-texel squares in two colours.
fn checker(w: usize, h: usize, cell: usize, c0: [u8; 4], c1: [u8; 4]) -> Vec<u8> {
    let mut v = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            v.extend_from_slice(if (x / cell + y / cell).is_multiple_of(2) {
                &c0
            } else {
                &c1
            });
        }
    }
    v
}

/// A colourful RGBA pattern: ramps in r and g, a checker in b, alpha
/// falling along the diagonal.
fn pattern(w: usize, h: usize) -> Vec<u8> {
    let mut v = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let (fx, fy) = (x as f32 / (w - 1).max(1) as f32, y as f32 / (h - 1).max(1) as f32);
            v.extend([
                (255.0 * fx) as u8,
                (255.0 * fy) as u8,
                if (x + y) % 2 == 0 { 230 } else { 40 },
                (255.0 * (1.0 - 0.8 * (fx + fy) / 2.0)) as u8,
            ]);
        }
    }
    v
}

/// The `components` channels of each RGBA texel kept (1: r; 2: r, a; 3: rgb).
fn channels(rgba: &[u8], components: usize) -> Vec<u8> {
    rgba.chunks(4)
        .flat_map(|p| match components {
            1 => vec![p[0]],
            2 => vec![p[0], p[3]],
            3 => vec![p[0], p[1], p[2]],
            _ => p.to_vec(),
        })
        .collect()
}

/// A mipmap pyramid whose level `l` is a checker of `cell >> l` texels in
/// its own pair of colours, so the level each pixel reads shows.
fn tinted_pyramid(size: usize, cell: usize) -> Vec<Level> {
    const TINTS: [([u8; 4], [u8; 4]); 7] = [
        ([240, 240, 240, 255], [30, 60, 160, 255]),
        ([250, 200, 60, 255], [90, 20, 20, 255]),
        ([80, 230, 90, 255], [20, 70, 30, 200]),
        ([230, 90, 230, 255], [60, 0, 90, 255]),
        ([90, 230, 230, 160], [0, 90, 110, 255]),
        ([200, 200, 90, 255], [110, 60, 0, 255]),
        ([255, 128, 0, 255], [0, 128, 255, 255]),
    ];
    let mut v = Vec::new();
    let mut n = size;
    let mut l = 0;
    loop {
        let (c0, c1) = TINTS[l % TINTS.len()];
        v.push((n, n, checker(n, n, (cell >> l).max(1), c0, c1)));
        if n == 1 {
            return v;
        }
        n /= 2;
        l += 1;
    }
}

/// Binds `name` on `target` and sets its filters and wraps (s, t and r);
/// every other parameter back to GL's default, as a replayed frame must
/// find it.
fn params(r: &mut Rec, target: TextureTarget, name: u32, min: (Filter, MipFilter), mag: Filter, wrap: Wrap) {
    r.call(Call::BindTexture(target, name));
    for p in [
        TexParam::MinFilter(min.0, min.1),
        TexParam::MagFilter(mag),
        TexParam::WrapS(wrap),
        TexParam::WrapT(wrap),
        TexParam::WrapR(wrap),
        TexParam::BorderColor([0.0; 4]),
        TexParam::MinLod(-1000.0),
        TexParam::MaxLod(1000.0),
        TexParam::BaseLevel(0),
        TexParam::MaxLevel(1000),
        TexParam::LodBias(0.0),
        TexParam::CompareMode(false),
    ] {
        r.tex_parameter(target, p);
    }
}

/// The texturing state of units 0 and 1 back to GL's defaults (targets and
/// texgen off, MODULATE, no unit LOD bias), unit 0 active: each texture
/// scene starts with it, so a replayed frame starts where the first did.
fn tex_reset(r: &mut Rec) {
    for unit in [1, 0] {
        r.call(Call::ActiveTexture(unit));
        for t in [TextureTarget::D1, T2, TextureTarget::D3, TextureTarget::Cube] {
            r.disable(Capability::Texture(t));
        }
        for c in [TexCoordName::S, TexCoordName::T, TexCoordName::R, TexCoordName::Q] {
            r.disable(Capability::TexGen(c));
        }
        r.tex_env(TexEnvParam::Mode(EnvMode::Modulate))
            .tex_env(TexEnvParam::LodBias(0.0));
    }
}

/// Uploads RGBA levels to the bound 2D texture (level 0 first).
fn upload_2d(r: &mut Rec, levels: &[Level]) {
    for (l, (w, h, d)) in levels.iter().enumerate() {
        r.tex_image(
            TexImageTarget::D2,
            l as i32,
            InternalFormat::Rgba,
            PixelFormat::Rgba,
            [*w as i32, *h as i32, 1],
            d,
        );
    }
}

/// Texture `name`: 2D, RGBA, `levels`, with filters and wrap, enabled.
fn texture_2d(r: &mut Rec, name: u32, levels: &[Level], min: (Filter, MipFilter), mag: Filter, wrap: Wrap) {
    params(r, T2, name, min, mag, wrap);
    upload_2d(r, levels);
    r.enable(Capability::Texture(T2));
}

fn env_mode(r: &mut Rec, m: EnvMode) -> &mut Rec {
    r.tex_env(TexEnvParam::Mode(m))
}

// ------------------------------------------------------------------ geometry

/// A quad as two triangles with a texture coordinate per corner
/// (`st[i]` for the corners (x0,y0), (x1,y0), (x0,y1), (x1,y1)).
fn tex_rect(r: &mut Rec, [x0, y0, x1, y1]: [f32; 4], z: f32, st: [[f32; 4]; 4]) {
    r.begin(PrimitiveMode::TriangleStrip);
    for (i, (x, y)) in [(x0, y0), (x1, y0), (x0, y1), (x1, y1)].into_iter().enumerate() {
        r.call(Call::TexCoord(0, st[i])).vertex(x, y, z);
    }
    r.end();
}

/// Corner coordinates spanning `[s0, s1] x [t0, t1]`.
fn span(s0: f32, s1: f32, t0: f32, t1: f32) -> [[f32; 4]; 4] {
    [
        [s0, t0, 0.0, 1.0],
        [s1, t0, 0.0, 1.0],
        [s0, t1, 0.0, 1.0],
        [s1, t1, 0.0, 1.0],
    ]
}

/// A panel inset by `m` pixels.
fn inset([x0, y0, x1, y1]: [f32; 4], m: f32) -> [f32; 4] {
    [x0 + m, y0 + m, x1 - m, y1 - m]
}

/// A perspective view down -z, the horizon near the top: a plane at y = -1
/// fills the lower five sixths.
fn receding_view(r: &mut Rec) {
    r.matrix_mode(MatrixMode::Projection)
        .load_identity()
        .frustum(-0.5, 0.5, -0.5, 0.1, 1.0, 200.0)
        .matrix_mode(MatrixMode::Modelview)
        .load_identity()
        .clear_color(0.45, 0.55, 0.7, 1.0)
        .clear(softgl::ClearMask::ALL);
}

/// The plane y = -1 from z = -1.2 to -120, x in ±60, its texture coordinates
/// x / 4 and z / 4 (so `repeat` copies down its length), in 8 strips.
fn receding_plane(r: &mut Rec, color: [f32; 4]) {
    r.color(color[0], color[1], color[2], color[3]);
    for i in 0..8 {
        let (z0, z1) = (
            -1.2 - 118.8 * (i as f32 / 8.0).powi(2),
            -1.2 - 118.8 * ((i + 1) as f32 / 8.0).powi(2),
        );
        r.begin(PrimitiveMode::TriangleStrip);
        for (x, z) in [(-60.0, z0), (60.0, z0), (-60.0, z1), (60.0, z1)] {
            r.tex_coord(x / 4.0, z / 4.0).vertex(x, -1.0, z);
        }
        r.end();
    }
}

// -------------------------------------------------------------------- scenes

/// A 64x64 checker with tinted mipmaps on a receding plane, magnified near
/// the viewer and minified down to the last level at the horizon.
fn receding_checker(r: &mut Rec, _s: Size, min: (Filter, MipFilter)) {
    tex_reset(r);
    receding_view(r);
    let levels = tinted_pyramid(64, 8);
    let levels = if min.1 == MipFilter::None {
        &levels[..1]
    } else {
        &levels[..]
    };
    texture_2d(r, 1, levels, min, Filter::Linear, Wrap::Repeat);
    env_mode(r, EnvMode::Replace);
    receding_plane(r, [1.0; 4]);
}

/// An 8x8 pattern stretched over most of the window, turned by 17° so no
/// texel edge lies on a pixel row, modulated by a smooth colour.
fn magnified(r: &mut Rec, s: Size, mag: Filter) {
    tex_reset(r);
    texture_2d(r, 1, &[(8, 8, pattern(8, 8))], NEAREST, mag, Wrap::Repeat);
    env_mode(r, EnvMode::Modulate);
    r.translate(s.wf() / 2.0, s.hf() / 2.0, 0.0)
        .call(Call::Rotate(17.0, [0.0, 0.0, 1.0]));
    let h = s.wf() * 0.42;
    r.begin(PrimitiveMode::TriangleStrip);
    for (x, y, c) in [
        (-h, -h, [1.0, 1.0, 1.0]),
        (h, -h, [1.0, 0.8, 0.6]),
        (-h, h, [0.6, 0.8, 1.0]),
        (h, h, [1.0; 3]),
    ] {
        r.color(c[0], c[1], c[2], 1.0)
            .tex_coord(if x < 0.0 { -0.25 } else { 1.25 }, if y < 0.0 { -0.25 } else { 1.25 })
            .vertex(x, y, 0.0);
    }
    r.end();
}

/// The texture coordinates run from -1.5 to 2.5 across each half of the
/// window: the left half NEAREST, the right half LINEAR, both with `wrap`
/// and a border colour.
fn wrapped(r: &mut Rec, s: Size, wrap: Wrap) {
    tex_reset(r);
    let halves = [[0.0, 0.0, s.wf() / 2.0, s.hf()], [s.wf() / 2.0, 0.0, s.wf(), s.hf()]];
    for (i, (half, f)) in halves.into_iter().zip([Filter::Nearest, Filter::Linear]).enumerate() {
        let name = i as u32 + 1;
        texture_2d(r, name, &[(8, 8, pattern(8, 8))], (f, MipFilter::None), f, wrap);
        r.tex_parameter(T2, TexParam::BorderColor([1.0, 0.5, 0.0, 0.5]));
        env_mode(r, EnvMode::Replace);
        tex_rect(r, inset(half, 2.0), 0.0, span(-1.5, 2.5, -1.5, 2.5));
    }
}

/// The six base formats as (internal format, client format, components).
const BASES: [(InternalFormat, PixelFormat, usize); 6] = [
    (InternalFormat::Rgba, PixelFormat::Rgba, 4),
    (InternalFormat::Rgb, PixelFormat::Rgb, 3),
    (InternalFormat::Luminance, PixelFormat::Luminance, 1),
    (InternalFormat::LuminanceAlpha, PixelFormat::LuminanceAlpha, 2),
    (InternalFormat::Alpha, PixelFormat::Alpha, 1),
    (InternalFormat::Intensity, PixelFormat::Luminance, 1),
];

/// Six smooth-shaded lit spheres, one per base format of a 16x16
/// texture (RGBA, RGB, L, LA, A, I), in environment `mode` (BLEND's
/// colour set), alpha from the material.
fn env_spheres(r: &mut Rec, _s: Size, mode: EnvMode) {
    tex_reset(r);
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.8, 0.6, 0.3, 0.7], 24.0);
    r.tex_env(TexEnvParam::Color([0.2, 0.6, 0.9, 0.5]));
    env_mode(r, mode);
    let texels = pattern(16, 16);
    for (i, (internal, format, comps)) in BASES.into_iter().enumerate() {
        params(r, T2, i as u32 + 1, LINEAR, Filter::Linear, Wrap::Repeat);
        r.tex_image(
            TexImageTarget::D2,
            0,
            internal,
            format,
            [16, 16, 1],
            &channels(&texels, comps),
        );
        r.enable(Capability::Texture(T2));
        let (x, y) = (-3.0 + 3.0 * (i % 3) as f32, 1.6 - 3.2 * (i / 3) as f32);
        sphere_with(r, [x, y, -9.0], 1.4, (20, 14), 1.0, SphereTex::Glu);
    }
}

/// One combine stage on the active unit.
/// (RGB function, alpha function, sources 0..2 for both, RGB operands,
/// RGB scale; the alpha operands are SRC_ALPHA, ONE_MINUS_SRC_ALPHA,
/// SRC_ALPHA and the alpha scale 2 where the RGB scale is over 1).
type Stage = (CombineFn, CombineFn, [CombineSrc; 3], [Operand; 3], f32);

fn combine(r: &mut Rec, (rgb, alpha, src, op_rgb, scale): Stage) {
    env_mode(r, EnvMode::Combine)
        .tex_env(TexEnvParam::CombineRgb(rgb))
        .tex_env(TexEnvParam::CombineAlpha(alpha))
        .tex_env(TexEnvParam::RgbScale(scale))
        .tex_env(TexEnvParam::AlphaScale(if scale > 1.0 { 2.0 } else { 1.0 }));
    for n in 0..3u8 {
        let i = usize::from(n);
        let op_alpha = if i == 1 {
            Operand::OneMinusSrcAlpha
        } else {
            Operand::SrcAlpha
        };
        r.tex_env(TexEnvParam::SrcRgb(n, src[i]))
            .tex_env(TexEnvParam::OperandRgb(n, op_rgb[i]))
            .tex_env(TexEnvParam::SrcAlpha(n, src[i]))
            .tex_env(TexEnvParam::OperandAlpha(n, op_alpha));
    }
}

/// Unit 0 and 1 each with a 2D texture (unit 0 the pattern, unit 1 a
/// checker), linear, repeat, enabled.
fn two_units(r: &mut Rec) {
    r.call(Call::ActiveTexture(0));
    texture_2d(r, 1, &[(8, 8, pattern(8, 8))], LINEAR, Filter::Linear, Wrap::Repeat);
    r.call(Call::ActiveTexture(1));
    let c = checker(4, 4, 1, [250, 220, 40, 200], [40, 90, 220, 100]);
    texture_2d(r, 2, &[(4, 4, c)], LINEAR, Filter::Linear, Wrap::Repeat);
}

/// Nine panels over two units: unit 0 MODULATE, unit 1 COMBINE with each
/// function (sources previous, texture and the constant colour; operands
/// and scales varied), the ninth reading `GL_TEXTURE0` from unit 1 and
/// `GL_TEXTURE1` from unit 0 (the crossbar). Smooth primary colours.
fn combine_functions(r: &mut Rec, s: Size) {
    tex_reset(r);
    use CombineFn::*;
    use CombineSrc::*;
    use Operand::*;
    two_units(r);
    r.tex_env(TexEnvParam::Color([0.3, 0.7, 0.5, 0.6]));
    #[rustfmt::skip]
    let stages = [
        (Replace, Replace, [Texture, Previous, Constant], [OneMinusSrcColor, SrcColor, SrcColor], 1.0),
        (Modulate, Modulate, [Previous, Texture, Constant], [SrcColor, SrcColor, SrcColor], 2.0),
        (Add, Add, [Previous, Texture, Constant], [SrcColor, OneMinusSrcColor, SrcColor], 1.0),
        (AddSigned, AddSigned, [Previous, Texture, Constant], [SrcColor, SrcColor, SrcColor], 2.0),
        (Interpolate, Interpolate, [Previous, Texture, Constant], [SrcColor, SrcColor, SrcAlpha], 1.0),
        (Subtract, Subtract, [Texture, Previous, Constant], [SrcColor, SrcAlpha, SrcColor], 4.0),
        (Dot3Rgb, Modulate, [Previous, Texture, Constant], [SrcColor, SrcColor, SrcColor], 1.0),
        (Dot3Rgba, Add, [Texture, PrimaryColor, Constant], [SrcColor, OneMinusSrcColor, SrcColor], 1.0),
    ];
    let p = panels(9, s);
    for (i, stage) in stages.into_iter().enumerate() {
        combine(r, stage);
        r.call(Call::ActiveTexture(0));
        env_mode(r, EnvMode::Modulate);
        r.call(Call::ActiveTexture(1));
        two_coord_rect(r, inset(p[i], 2.0));
    }
    // The crossbar: unit 0 interpolates its texture with unit 1's, unit 1
    // subtracts unit 0's from the result.
    #[rustfmt::skip]
    let crossbar: [Stage; 2] = [
        (Interpolate, Replace, [Texture, TextureUnit(1), PrimaryColor], [SrcColor; 3], 1.0),
        (Subtract, Modulate, [Previous, TextureUnit(0), Constant], [SrcColor, OneMinusSrcColor, SrcColor], 2.0),
    ];
    for (unit, stage) in crossbar.into_iter().enumerate() {
        r.call(Call::ActiveTexture(unit as u32));
        combine(r, stage);
    }
    two_coord_rect(r, inset(p[8], 2.0));
}

/// A quad with smooth colours and two texture coordinate sets (unit 1's
/// turned and scaled against unit 0's).
fn two_coord_rect(r: &mut Rec, [x0, y0, x1, y1]: [f32; 4]) {
    r.begin(PrimitiveMode::TriangleStrip);
    let corners = [
        (x0, y0, [1.0, 0.2, 0.2, 1.0], [0.0, 0.0], [0.3, -0.2]),
        (x1, y0, [0.2, 1.0, 0.2, 0.8], [1.0, 0.0], [2.1, 0.4]),
        (x0, y1, [0.2, 0.2, 1.0, 0.5], [0.0, 1.0], [-0.3, 1.6]),
        (x1, y1, [1.0, 1.0, 1.0, 0.2], [1.0, 1.0], [1.5, 2.2]),
    ];
    for (x, y, c, t0, t1) in corners {
        two_coord_vertex(r, (x, y), c, t0, t1);
    }
    r.end();
}

/// A vertex at z = 0 with a colour and coordinates for units 0 and 1.
fn two_coord_vertex(r: &mut Rec, (x, y): (f32, f32), c: [f32; 4], t0: [f32; 2], t1: [f32; 2]) {
    r.color(c[0], c[1], c[2], c[3])
        .call(Call::TexCoord(0, [t0[0], t0[1], 0.0, 1.0]))
        .call(Call::TexCoord(1, [t1[0], t1[1], 0.0, 1.0]))
        .vertex(x, y, 0.0);
}

/// DOT3 bump mapping: unit 0 takes the dot product of a normal map (a
/// dome of bumps, normals encoded 0.5 + n/2) with the light direction
/// encoded in the primary colour; unit 1 modulates that with a base
/// texture. Left: DOT3_RGB; right: DOT3_RGBA.
fn dot3_bump(r: &mut Rec, s: Size) {
    tex_reset(r);
    let n = 32;
    let mut normals = Vec::with_capacity(n * n * 4);
    for y in 0..n {
        for x in 0..n {
            let (u, v) = (((x % 8) as f32 - 3.5) / 4.0, ((y % 8) as f32 - 3.5) / 4.0);
            let nz = (1.0 - (u * u + v * v).min(0.95)).sqrt();
            let len = (u * u + v * v + nz * nz).sqrt();
            let enc = |c: f32| (127.5 + 127.5 * c / len).round().clamp(0.0, 255.0) as u8;
            normals.extend([enc(u), enc(v), enc(nz), 255]);
        }
    }
    r.call(Call::ActiveTexture(0));
    texture_2d(r, 1, &[(n, n, normals)], LINEAR, Filter::Linear, Wrap::Repeat);
    r.call(Call::ActiveTexture(1));
    texture_2d(r, 2, &[(8, 8, pattern(8, 8))], NEAREST, Filter::Linear, Wrap::Repeat);
    use CombineSrc::*;
    use Operand::SrcColor;
    let halves = [[0.0, 0.0, s.wf() / 2.0, s.hf()], [s.wf() / 2.0, 0.0, s.wf(), s.hf()]];
    for (half, dot) in halves.into_iter().zip([CombineFn::Dot3Rgb, CombineFn::Dot3Rgba]) {
        #[rustfmt::skip]
        let stages: [Stage; 2] = [
            (dot, CombineFn::Replace, [Texture, PrimaryColor, Constant], [SrcColor; 3], 1.0),
            (CombineFn::Modulate, CombineFn::Modulate, [Previous, Texture, Constant], [SrcColor; 3], 1.0),
        ];
        for (unit, stage) in stages.into_iter().enumerate() {
            r.call(Call::ActiveTexture(unit as u32));
            combine(r, stage);
        }
        // The light direction, encoded, changing across the quad.
        let [x0, y0, x1, y1] = inset(half, 2.0);
        r.begin(PrimitiveMode::TriangleStrip);
        for (x, y, l) in [
            (x0, y0, [0.8, 0.5, 0.7]),
            (x1, y0, [0.2, 0.5, 0.9]),
            (x0, y1, [0.5, 0.9, 0.6]),
            (x1, y1, [0.5, 0.1, 0.8]),
        ] {
            let (st, st1) = ([(x - x0) / 24.0, (y - y0) / 24.0], [(x - x0) / 40.0, (y - y0) / 40.0]);
            two_coord_vertex(r, (x, y), [l[0], l[1], l[2], 1.0], st, st1);
        }
        r.end();
    }
}

/// A 1D ramp with its mipmaps on the receding plane (s along x, LINEAR
/// MIPMAP LINEAR) and, above the horizon, a NEAREST copy across the sky.
fn tex_1d(r: &mut Rec, _s: Size) {
    tex_reset(r);
    receding_view(r);
    let t1 = TextureTarget::D1;
    params(r, t1, 1, TRILINEAR, Filter::Nearest, Wrap::MirroredRepeat);
    let mut n = 64usize;
    let mut l = 0;
    loop {
        let texels: Vec<u8> = (0..n)
            .flat_map(|i| {
                let f = i as f32 / n as f32;
                [
                    (255.0 * f) as u8,
                    (40 * (l + 1)) as u8,
                    if i % 2 == 0 { 200 } else { 20 },
                    255,
                ]
            })
            .collect();
        r.tex_image(
            TexImageTarget::D1,
            l,
            InternalFormat::Rgba,
            PixelFormat::Rgba,
            [n as i32, 1, 1],
            &texels,
        );
        if n == 1 {
            break;
        }
        n /= 2;
        l += 1;
    }
    r.enable(Capability::Texture(t1));
    env_mode(r, EnvMode::Modulate);
    receding_plane(r, [1.0, 0.9, 0.8, 1.0]);
    // The sky band: s over the width, at z = -2.
    r.tex_parameter(t1, TexParam::MinFilter(Filter::Nearest, MipFilter::None));
    r.begin(PrimitiveMode::TriangleStrip);
    for (x, y, s) in [
        (-1.0, 0.05, -0.3),
        (1.0, 0.05, 1.7),
        (-1.0, 0.18, -0.3),
        (1.0, 0.18, 1.7),
    ] {
        r.tex_coord(s, 0.0).vertex(x, y, -2.0);
    }
    r.end();
}

/// A 16x16x16 RGBA volume (ramps in r, g, b along s, t, r; a checker in
/// alpha) in four panels: a NEAREST slice, an oblique LINEAR slice, a
/// minified LINEAR_MIPMAP_LINEAR view and CLAMP_TO_EDGE beyond [0, 1].
fn tex_3d(r: &mut Rec, s: Size) {
    tex_reset(r);
    let t3 = TextureTarget::D3;
    let mut n = 16usize;
    let mut levels = Vec::new();
    while n >= 1 {
        let mut v = Vec::with_capacity(n * n * n * 4);
        for z in 0..n {
            for y in 0..n {
                for x in 0..n {
                    let f = |c: usize| (255 * c / n.max(2).saturating_sub(1).max(1)).min(255) as u8;
                    v.extend([f(x), f(y), f(z), if (x + y + z) % 2 == 0 { 255 } else { 96 }]);
                }
            }
        }
        levels.push((n, v));
        if n == 1 {
            break;
        }
        n /= 2;
    }
    let p = panels(4, s);
    let setups = [
        (NEAREST, Filter::Nearest, Wrap::Repeat),
        (LINEAR, Filter::Linear, Wrap::Repeat),
        (TRILINEAR, Filter::Linear, Wrap::Repeat),
        (LINEAR, Filter::Linear, Wrap::ClampToEdge),
    ];
    let coords: [[[f32; 4]; 4]; 4] = [
        [
            [0.0, 0.0, 0.4, 1.0],
            [1.0, 0.0, 0.4, 1.0],
            [0.0, 1.0, 0.4, 1.0],
            [1.0, 1.0, 0.4, 1.0],
        ],
        [
            [0.0, 0.0, 0.0, 1.0],
            [1.0, 0.0, 0.5, 1.0],
            [0.0, 1.0, 0.5, 1.0],
            [1.0, 1.0, 1.0, 1.0],
        ],
        [
            [0.0, 0.0, 0.0, 1.0],
            [6.0, 0.0, 3.0, 1.0],
            [0.0, 6.0, 3.0, 1.0],
            [6.0, 6.0, 6.0, 1.0],
        ],
        [
            [-0.5, -0.5, -0.5, 1.0],
            [1.5, -0.5, 0.5, 1.0],
            [-0.5, 1.5, 0.5, 1.0],
            [1.5, 1.5, 1.5, 1.0],
        ],
    ];
    for (i, (min, mag, wrap)) in setups.into_iter().enumerate() {
        params(r, t3, i as u32 + 1, min, mag, wrap);
        let count = if min.1 == MipFilter::None { 1 } else { levels.len() };
        for (l, (n, v)) in levels.iter().take(count).enumerate() {
            let n = *n as i32;
            r.tex_image(
                TexImageTarget::D3,
                l as i32,
                InternalFormat::Rgba,
                PixelFormat::Rgba,
                [n, n, n],
                v,
            );
        }
        r.enable(Capability::Texture(t3));
        env_mode(r, EnvMode::Replace);
        tex_rect(r, inset(p[i], 2.0), 0.0, coords[i]);
    }
}

/// A cube map (six 16x16 faces, each a checker in its own colours) on two
/// lit spheres: the left with the normal as (s, t, r), the right with
/// `GL_NORMAL_MAP` texgen; LINEAR, CLAMP_TO_EDGE.
fn cube_map(r: &mut Rec, _s: Size) {
    tex_reset(r);
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.9, 0.9, 0.9, 1.0], 16.0);
    let tc = TextureTarget::Cube;
    params(r, tc, 1, LINEAR, Filter::Linear, Wrap::ClampToEdge);
    let faces = [
        ([230, 60, 60, 255], [90, 10, 10, 255]),
        ([60, 230, 230, 255], [10, 90, 90, 255]),
        ([60, 230, 60, 255], [10, 90, 10, 255]),
        ([230, 60, 230, 255], [90, 10, 90, 255]),
        ([60, 60, 230, 255], [10, 10, 90, 255]),
        ([230, 230, 60, 255], [90, 90, 10, 255]),
    ];
    for (f, (c0, c1)) in faces.into_iter().enumerate() {
        let mut texels = checker(16, 16, 4, c0, c1);
        // Mark each face's first texel, so orientation errors show.
        texels[..4].copy_from_slice(&[255, 255, 255, 255]);
        r.tex_image(
            TexImageTarget::CubeFace(f as u8),
            0,
            InternalFormat::Rgba,
            PixelFormat::Rgba,
            [16, 16, 1],
            &texels,
        );
    }
    r.enable(Capability::Texture(tc));
    env_mode(r, EnvMode::Modulate);
    // Left: (s, t, r) = the normal, set per vertex.
    sphere_with(r, [-2.2, 0.0, -9.0], 2.0, (24, 16), 1.0, SphereTex::Normal);
    // Right: generated from the eye-space normal.
    for c in [TexCoordName::S, TexCoordName::T, TexCoordName::R] {
        r.call(Call::TexGen(c, TexGenParam::Mode(TexGenMode::NormalMap)))
            .enable(Capability::TexGen(c));
    }
    sphere_with(r, [2.2, 0.0, -9.0], 2.0, (24, 16), 1.0, SphereTex::Normal);
}

/// Two lit spheres with `GL_SPHERE_MAP` texgen on s and t, a 64x64
/// environment image with its mipmaps (LINEAR_MIPMAP_LINEAR), MODULATE.
fn sphere_map(r: &mut Rec, _s: Size) {
    tex_reset(r);
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.9, 0.85, 0.8, 1.0], 32.0);
    let levels = tinted_pyramid(64, 8);
    texture_2d(r, 1, &levels, TRILINEAR, Filter::Linear, Wrap::Repeat);
    env_mode(r, EnvMode::Modulate);
    for c in [TexCoordName::S, TexCoordName::T] {
        r.call(Call::TexGen(c, TexGenParam::Mode(TexGenMode::SphereMap)))
            .enable(Capability::TexGen(c));
    }
    sphere_with(r, [-2.2, 0.0, -9.0], 2.0, (24, 16), 1.0, SphereTex::None);
    sphere_with(r, [2.2, 0.0, -7.0], 1.5, (9, 6), 1.0, SphereTex::None);
}

/// A 64x64 depth texture (a disc of depth 0.3, a ramp 0.2..0.9 across the
/// rest) compared with r by `GL_COMPARE_R_TO_TEXTURE` in four panels:
/// LEQUAL as luminance (LINEAR: compare then filter), GEQUAL as intensity
/// (NEAREST), LESS as alpha (LINEAR), GREATER with r beyond [0, 1].
/// The quads' r runs 0..1 against the map, over a smooth colour (MODULATE).
fn shadow_map(r: &mut Rec, s: Size) {
    tex_reset(r);
    let n = 64usize;
    let mut depth = Vec::with_capacity(n * n * 4);
    for y in 0..n {
        for x in 0..n {
            let (dx, dy) = (x as f32 - 24.0, y as f32 - 36.0);
            let d = if dx * dx + dy * dy < 150.0 {
                0.3
            } else {
                0.2 + 0.7 * x as f32 / (n - 1) as f32
            };
            depth.extend(f32::to_ne_bytes(d));
        }
    }
    let p = panels(4, s);
    let setups = [
        (CompareFunc::Lequal, DepthMode::Luminance, Filter::Linear, (0.0, 1.0)),
        (CompareFunc::Gequal, DepthMode::Intensity, Filter::Nearest, (0.0, 1.0)),
        (CompareFunc::Less, DepthMode::Alpha, Filter::Linear, (0.1, 0.9)),
        (CompareFunc::Greater, DepthMode::Luminance, Filter::Linear, (-0.5, 1.5)),
    ];
    env_mode(r, EnvMode::Modulate);
    for (i, (func, mode, filter, (r0, r1))) in setups.into_iter().enumerate() {
        params(
            r,
            T2,
            i as u32 + 1,
            (filter, MipFilter::None),
            filter,
            Wrap::ClampToEdge,
        );
        r.tex_parameter(T2, TexParam::CompareMode(true))
            .tex_parameter(T2, TexParam::CompareFunc(func))
            .tex_parameter(T2, TexParam::DepthMode(mode))
            .call(Call::TexImage {
                target: TexImageTarget::D2,
                level: 0,
                internal: InternalFormat::DepthComponent,
                size: [n as i32, n as i32, 1],
                format: PixelFormat::DepthComponent,
                ty: PixelType::Float,
                pixels: depth.clone(),
            })
            .enable(Capability::Texture(T2));
        let [x0, y0, x1, y1] = inset(p[i], 2.0);
        r.begin(PrimitiveMode::TriangleStrip);
        for (x, y, sc, tc, rc, c) in [
            (x0, y0, 0.0, 0.0, r0, [1.0, 0.8, 0.6, 1.0]),
            (x1, y0, 1.0, 0.0, r1, [0.9, 0.9, 0.9, 0.9]),
            (x0, y1, 0.0, 1.0, r1, [0.6, 0.8, 1.0, 0.8]),
            (x1, y1, 1.0, 1.0, r0, [1.0, 1.0, 1.0, 1.0]),
        ] {
            r.color(c[0], c[1], c[2], c[3])
                .call(Call::TexCoord(0, [sc, tc, rc, 1.0]))
                .vertex(x, y, 0.0);
        }
        r.end();
    }
}

/// A 200x90 RGBA image (rings and stripes) with the levels
/// `gluBuild2DMipmaps` makes of it (256x64 down to 1x1), trilinear on the
/// receding plane.
fn npot_mipmaps(r: &mut Rec, _s: Size) {
    tex_reset(r);
    let (w, h) = (200usize, 90usize);
    let mut img = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let (dx, dy) = (x as f32 - 100.0, y as f32 - 45.0);
            let ring = ((dx * dx + dy * dy).sqrt() / 6.0) as u32 % 2;
            img.extend([
                if ring == 0 { 240 } else { 30 },
                ((x * 255) / w) as u8,
                if (y / 5) % 2 == 0 { 200 } else { 60 },
                255 - (y * 2) as u8,
            ]);
        }
    }
    receding_view(r);
    let levels = glu::build_2d_mipmaps(4, w, h, &img);
    texture_2d(r, 1, &levels, TRILINEAR, Filter::Linear, Wrap::Repeat);
    env_mode(r, EnvMode::Replace);
    receding_plane(r, [1.0; 4]);
}

/// A 1x1 texture (with its one level as the whole pyramid) under LINEAR
/// MIPMAP LINEAR in three panels: REPEAT, CLAMP_TO_BORDER (coordinates
/// -1..2, so the border blends in), MIRRORED_REPEAT with coordinates
/// ±1000.
fn one_by_one(r: &mut Rec, s: Size) {
    tex_reset(r);
    let p = panels(3, s);
    let spans = [
        span(0.0, 1.0, 0.0, 1.0),
        span(-1.0, 2.0, -1.0, 2.0),
        span(-1000.0, 1000.0, 1000.0, -1000.0),
    ];
    env_mode(r, EnvMode::Modulate);
    for (i, wrap) in [Wrap::Repeat, Wrap::ClampToBorder, Wrap::MirroredRepeat]
        .into_iter()
        .enumerate()
    {
        texture_2d(
            r,
            i as u32 + 1,
            &[(1, 1, vec![200, 120, 40, 220])],
            TRILINEAR,
            Filter::Linear,
            wrap,
        );
        r.tex_parameter(T2, TexParam::BorderColor([0.1, 0.9, 0.3, 1.0]));
        r.color(0.9, 1.0, 0.8, 1.0);
        tex_rect(r, inset(p[i], 2.0), 0.0, spans[i]);
    }
}

/// A 4096x1 texture of stripes (13 levels, box-filtered as GLU halves a
/// line) on the receding plane under LINEAR_MIPMAP_LINEAR, and a NEAREST
/// band across the sky reading level 0 only.
fn wide(r: &mut Rec, _s: Size) {
    tex_reset(r);
    let n = 4096usize;
    let base: Vec<u8> = (0..n)
        .flat_map(|i| {
            let stripe = (i / 3) % 2 == 0;
            [
                if stripe { 250 } else { 10 },
                ((i * 255) / n) as u8,
                if i % 7 < 3 { 220 } else { 30 },
                255,
            ]
        })
        .collect();
    let levels = glu::build_2d_mipmaps(4, n, 1, &base);
    receding_view(r);
    texture_2d(r, 1, &levels, TRILINEAR, Filter::Linear, Wrap::Repeat);
    env_mode(r, EnvMode::Replace);
    receding_plane(r, [1.0; 4]);
    r.tex_parameter(T2, TexParam::MinFilter(Filter::Nearest, MipFilter::None));
    r.begin(PrimitiveMode::TriangleStrip);
    for (x, y, s) in [(-1.0, 0.05, 0.0), (1.0, 0.05, 1.0), (-1.0, 0.18, 0.0), (1.0, 0.18, 1.0)] {
        r.tex_coord(s, 0.5).vertex(x, y, -2.0);
    }
    r.end();
}

/// Texture coordinates near ±1e6 (where an f32 steps by 1/16 and 1/8) with
/// REPEAT, MIRRORED_REPEAT and CLAMP_TO_EDGE, LINEAR and NEAREST.
fn coords_1e6(r: &mut Rec, s: Size) {
    tex_reset(r);
    let p = panels(6, s);
    env_mode(r, EnvMode::Replace);
    let wraps = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
    for (i, (wrap, f)) in wraps
        .into_iter()
        .flat_map(|w| [(w, Filter::Linear), (w, Filter::Nearest)])
        .enumerate()
    {
        texture_2d(r, i as u32 + 1, &[(8, 8, pattern(8, 8))], (f, MipFilter::None), f, wrap);
        let (s0, t0) = if i % 2 == 0 {
            (1.0e6, -1.0e6)
        } else {
            (-1.0e6 - 3.0, 0.999e6)
        };
        tex_rect(r, inset(p[i], 2.0), 0.0, span(s0, s0 + 3.0, t0, t0 + 2.5));
    }
}

/// The receding checker in four bands: GL_TEXTURE_LOD_BIAS +100 on the
/// object, -100 on the object, +100 through the unit (`GL_TEXTURE_FILTER_CONTROL`)
/// with MAX_LOD 2, and -100 through the unit with BASE_LEVEL 1, MAX_LEVEL 3
/// and MIN_LOD 0.5 (the scissor picks each band).
fn lod_bias(r: &mut Rec, s: Size) {
    tex_reset(r);
    receding_view(r);
    let levels = tinted_pyramid(64, 8);
    texture_2d(r, 1, &levels, TRILINEAR, Filter::Nearest, Wrap::Repeat);
    env_mode(r, EnvMode::Replace);
    r.enable(Capability::ScissorTest);
    let band = s.wf() / 4.0;
    let settings: [&[Call]; 4] = [
        &[Call::TexParameter(T2, TexParam::LodBias(100.0))],
        &[Call::TexParameter(T2, TexParam::LodBias(-100.0))],
        &[
            Call::TexParameter(T2, TexParam::LodBias(0.0)),
            Call::TexEnv(TexEnvParam::LodBias(100.0)),
            Call::TexParameter(T2, TexParam::MaxLod(2.0)),
        ],
        &[
            Call::TexEnv(TexEnvParam::LodBias(-100.0)),
            Call::TexParameter(T2, TexParam::MaxLod(1000.0)),
            Call::TexParameter(T2, TexParam::BaseLevel(1)),
            Call::TexParameter(T2, TexParam::MaxLevel(3)),
            Call::TexParameter(T2, TexParam::MinLod(0.5)),
        ],
    ];
    for (i, calls) in settings.into_iter().enumerate() {
        for c in calls {
            r.call(c.clone());
        }
        r.scissor((band * i as f32) as i32, 0, band.ceil() as i32, s.h as i32);
        receding_plane(r, [1.0; 4]);
    }
    r.tex_env(TexEnvParam::LodBias(0.0));
}

/// Derivatives of the texture coordinates 0 (every vertex of the left
/// quads at one coordinate: magnification) and about 1e30 per pixel (the
/// right quads span ±1e30: the last level), mipmapped, NEAREST and LINEAR.
fn derivatives(r: &mut Rec, s: Size) {
    tex_reset(r);
    let p = panels(4, s);
    env_mode(r, EnvMode::Replace);
    let levels = tinted_pyramid(16, 2);
    let c = [0.3, 0.7, 0.0, 1.0];
    let spans = [[c; 4], span(-1.0e30, 1.0e30, 1.0e30, -1.0e30)];
    for (i, f) in [Filter::Linear, Filter::Nearest].into_iter().enumerate() {
        texture_2d(r, i as u32 + 1, &levels, (f, MipFilter::Linear), f, Wrap::Repeat);
        tex_rect(r, inset(p[2 * i], 2.0), 0.0, spans[0]);
        tex_rect(r, inset(p[2 * i + 1], 2.0), 0.0, spans[1]);
    }
}
