//! Framebuffer objects, blits, multisample resolve and occlusion queries
//! (issue 14): render-to-texture then sampling it on the window; blits
//! scaled, flipped, NEAREST and LINEAR, of colour, depth and stencil; a 4×
//! renderbuffer object resolved by a blit into a single-sampled one; and the
//! counts of occlusion queries, written into the image as colours
//! ([`Call::ClearColorFromQuery`]) so they are compared with llvmpipe's like
//! any pixel. The stiff cases are in [`stiff_scenes`] (group `stiff`).
//!
//! Object names are fixed per scene (GL's compatibility profile makes an
//! object at its first bind), and every scene ends with the window bound.

use super::stages::show_stencil;
use super::{gradient_background, random_triangles, Group, Near, Rng, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::fbo::{AttachmentPoint, BlitFilter, BlitMask, FramebufferTarget, RenderbufferFormat};
use softgl::{
    Capability, ClearMask, CompareFunc, EnvMode, Filter, InternalFormat, MatrixMode, MipFilter, PixelFormat,
    PrimitiveMode, StencilOp, TexEnvParam, TexImageTarget, TexParam, TextureTarget,
};

const G: Group = Group::Framebuffer;
const BOTH: FramebufferTarget = FramebufferTarget::Both;
const T2: TextureTarget = TextureTarget::D2;

/// Exact against llvmpipe (measured at 96x96 and 256x256).
const E: Tolerance = Tolerance {
    reason: "softgl renders into objects, blits (llvmpipe's blitter: NEAREST as its point sampler, LINEAR \
             through its AoS sampler, docs/llvmpipe-facts.md 25), resolves 4 samples and counts samples \
             as llvmpipe: identical at both sizes",
    ..Tolerance::EXACT
};

/// LINEAR blits (measured 2026-11-27).
const BLIT_LINEAR: Tolerance = Tolerance::lsb(
    38,
    234,
    "LINEAR blits may differ from llvmpipe's by 1 LSB on the pixels counted (its AoS sampler's 8-bit \
     weights; NEAREST and 1:1 blits are identical). Measured 2026-11-27.",
);

/// Magnified LINEAR sampling of the rendered texture (measured).
const TEX_LINEAR: Tolerance = Tolerance::lsb(
    0,
    18,
    "Rendering into the texture and sampling it NEAREST are identical; its LINEAR magnification may differ \
     by 1 LSB on the pixels counted at 256x256 (measured 2026-11-27).",
);

/// 4x resolve (measured).
const MSAA: Tolerance = Tolerance::lsb(
    0,
    9,
    "The 4x object's resolve is identical at 96x96; at 256x256 9 resolved pixels differ by 1 LSB \
     (a sample's colour on a triangle edge, f32 attribute setup: docs/llvmpipe-facts.md 11). Measured 2026-11-27.",
);

/// Counting into a 4x object (measured).
const MSAA_QUERY: Tolerance = Tolerance::lsb(
    0,
    1,
    "Both counts are identical to llvmpipe's; one resolved pixel differs by 1 LSB at 256x256 (measured 2026-11-27).",
);

/// Lines and points counted (measured).
const QUERY_LINES: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.001,
    coverage: 0,
    reason: "KNOWN DIFFERENCE (softgl's, reported): identical at 96x96; at 256x256 one of the random lines or \
             3-pixel points of query 7 covers a pixel one row off llvmpipe's ((109, 199) for (109, 200) and \
             (167, 198) for (167, 199)), so query 7 counts 6177 where llvmpipe counts 6176 (49 pixels, the \
             count's block included). Every other count is identical.",
};

/// The 8192x8192 object minified to the window (measured).
const BIG: Tolerance = Tolerance {
    channel: 1,
    near: Near { test: 10, report: 1 },
    share_over: 0.0002,
    coverage: 0,
    reason: "Rendering into the 8192x8192 object is identical; blitted down by 170x, NEAREST picks a \
             neighbouring texel on the pixels counted (as blit_flipped_and_minified). Measured 2026-11-27.",
};

/// Blits running off the window (measured).
const CLIPPED_BLIT: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.0015,
    coverage: 0,
    reason: "KNOWN DIFFERENCE (softgl's, reported): identical at 96x96; at 256x256 the NEAREST blit magnified \
             and clipped at the window's left and top edges gives row 204 the neighbouring source row \
             (85 pixels): softgl recomputes the clipped source rectangle otherwise than Mesa's \
             _mesa_clip_blit.",
};

/// Measured 2026-11-27 (96x96: 229 pixels; 256x256: see the report).
const FLIPPED: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.04,
    coverage: 0,
    reason: "KNOWN DIFFERENCE (softgl's, reported): scaled blits reversed in x or y, and minified NEAREST \
             blits, pick a neighbouring source column or row on some destination columns/rows where \
             llvmpipe's blitter (a quad whose texture coordinates are interpolated in f32) picks the other; \
             a reversed source running off the object is clipped to another destination rectangle. \
             Measured 2026-11-27: whole columns/rows of those blits, 2.5% of the pixels at 96x96, 1.5% at 256x256.",
};

/// Measured 2026-11-27.
const MSAA_LINES: Tolerance = Tolerance {
    channel: 0,
    near: Near::NONE,
    share_over: 0.005,
    coverage: 1,
    reason: "KNOWN DIFFERENCE (softgl's, reported): 2-pixel-wide lines into a 4x object cover a few samples \
             differently from llvmpipe at line ends, so a few resolved pixels differ (measured 2026-11-27: \
             2 over 1 LSB at 96x96; 19 and one pixel of coverage at 256x256); the triangles of \
             msaa_4x_resolve agree.",
};

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("fbo_render_to_texture", G, TEX_LINEAR, render_to_texture),
        Scene::new("fbo_render_to_texture_mipmaps", G, E, render_to_texture_mipmaps),
        Scene::new("blit_color_scaled", G, BLIT_LINEAR, blit_color),
        Scene::new("blit_flipped_and_minified", G, FLIPPED, blit_flipped),
        Scene::new("blit_depth_stencil", G, E, blit_depth_stencil),
        Scene::new("msaa_4x_resolve", G, MSAA, msaa_resolve),
        Scene::new("msaa_4x_wide_lines", G, MSAA_LINES, msaa_lines),
        Scene::new("occlusion_query_counts", G, QUERY_LINES, occlusion_counts),
        Scene::new("occlusion_query_msaa", G, MSAA_QUERY, occlusion_msaa),
    ]
}

/// The stiff cases: a 1×1 and an 8192×8192 object, blits with negative and
/// reversed extents, and queries around no fragments at all.
pub fn stiff_scenes() -> Vec<Scene> {
    let g = Group::Stiff;
    vec![
        Scene::new("fbo_1x1", g, E, fbo_1x1),
        Scene::new("fbo_8192x8192", g, BIG, fbo_8192),
        Scene::new("blit_negative_extents", g, CLIPPED_BLIT, blit_negative_extents),
        Scene::new("query_zero_fragments", g, E, query_zero_fragments),
    ]
}

/// A pixel-unit orthographic view of a `w`×`h` target (z in `[-1, 1]`).
pub fn pixel_view(r: &mut Rec, w: u32, h: u32) {
    r.viewport(0, 0, w as i32, h as i32)
        .matrix_mode(MatrixMode::Projection)
        .load_identity()
        .ortho(0.0, w as f64, 0.0, h as f64, -1.0, 1.0)
        .matrix_mode(MatrixMode::Modelview)
        .load_identity()
        .scissor(0, 0, w as i32, h as i32);
}

/// Framebuffer `fb` with an RGBA8 renderbuffer `color` and a
/// DEPTH24_STENCIL8 renderbuffer `depth` of `samples` samples (0: single),
/// bound for drawing and reading.
pub fn renderbuffer_fbo(r: &mut Rec, fb: u32, color: u32, depth: u32, size: [i32; 2], samples: i32) {
    r.call(Call::BindRenderbuffer(color))
        .call(Call::RenderbufferStorage {
            samples,
            format: RenderbufferFormat::Rgba8,
            size,
        })
        .call(Call::BindRenderbuffer(depth))
        .call(Call::RenderbufferStorage {
            samples,
            format: RenderbufferFormat::Depth24Stencil8,
            size,
        })
        .call(Call::BindRenderbuffer(0))
        .call(Call::BindFramebuffer(BOTH, fb))
        .call(Call::FramebufferRenderbuffer(BOTH, AttachmentPoint::Color(0), color))
        .call(Call::FramebufferRenderbuffer(
            BOTH,
            AttachmentPoint::DepthStencil,
            depth,
        ));
}

pub const COLOR: BlitMask = BlitMask {
    color: true,
    depth: false,
    stencil: false,
};

/// `glBlitFramebuffer` from the read to the draw binding.
pub fn blit(r: &mut Rec, src: [i32; 4], dst: [i32; 4], mask: BlitMask, filter: BlitFilter) {
    r.call(Call::BlitFramebuffer { src, dst, mask, filter });
}

/// Read from `read`, draw into `draw`.
pub fn bind_read_draw(r: &mut Rec, read: u32, draw: u32) {
    r.call(Call::BindFramebuffer(FramebufferTarget::Read, read))
        .call(Call::BindFramebuffer(FramebufferTarget::Draw, draw));
}

/// Something to look at in a `w`×`h` target: a gradient, then depth-tested
/// random triangles.
fn content(r: &mut Rec, w: u32, h: u32, full: bool, seed: u32, n: usize) {
    let s = Size { w, h, full };
    r.call(Call::ClearDepth(1.0)).clear(ClearMask::ALL);
    gradient_background(r, s);
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    random_triangles(
        r,
        &mut Rng::new(seed),
        s.count(n),
        s,
        (w.min(h) as f32 / 6.0).max(2.0),
        (1.0, 1.0),
    );
    r.disable(Capability::DepthTest);
}

/// A `w`×`h` RGBA8 texture `name` with no texels yet, NEAREST or LINEAR.
fn empty_texture(r: &mut Rec, name: u32, w: i32, h: i32, min: (Filter, MipFilter), mag: Filter) {
    r.call(Call::BindTexture(T2, name))
        .tex_image(
            TexImageTarget::D2,
            0,
            InternalFormat::Rgba8,
            PixelFormat::Rgba,
            [w, h, 1],
            &vec![0; (w * h * 4) as usize],
        )
        .tex_parameter(T2, TexParam::MinFilter(min.0, min.1))
        .tex_parameter(T2, TexParam::MagFilter(mag));
}

/// A textured axis-aligned quad, texture coordinates `t` = `[s0, t0, s1, t1]`.
fn textured_quad(r: &mut Rec, q: [f32; 4], t: [f32; 4]) {
    r.begin(PrimitiveMode::TriangleStrip)
        .tex_coord(t[0], t[1])
        .vertex(q[0], q[1], 0.0)
        .tex_coord(t[2], t[1])
        .vertex(q[2], q[1], 0.0)
        .tex_coord(t[0], t[3])
        .vertex(q[0], q[3], 0.0)
        .tex_coord(t[2], t[3])
        .vertex(q[2], q[3], 0.0)
        .end();
}

/// Draws into texture 1 (64×48) through framebuffer 1 (with a depth
/// renderbuffer), then samples it on the window: texel for pixel, NEAREST
/// magnified and rotated, LINEAR magnified.
fn render_to_texture(r: &mut Rec, s: Size) {
    let (tw, th) = (64, 48);
    empty_texture(r, 1, tw, th, (Filter::Nearest, MipFilter::None), Filter::Nearest);
    r.call(Call::BindRenderbuffer(2))
        .call(Call::RenderbufferStorage {
            samples: 0,
            format: RenderbufferFormat::Depth24Stencil8,
            size: [tw, th],
        })
        .call(Call::BindFramebuffer(BOTH, 1))
        .call(Call::FramebufferTexture2D(
            BOTH,
            AttachmentPoint::Color(0),
            TexImageTarget::D2,
            1,
            0,
        ))
        .call(Call::FramebufferRenderbuffer(BOTH, AttachmentPoint::DepthStencil, 2));
    pixel_view(r, tw as u32, th as u32);
    content(r, tw as u32, th as u32, s.full, 300, 120);
    r.call(Call::BindFramebuffer(BOTH, 0));
    pixel_view(r, s.w, s.h);
    r.clear_color(0.0, 0.0, 0.0, 0.0).clear(ClearMask::ALL);
    r.enable(Capability::Texture(T2))
        .tex_env(TexEnvParam::Mode(EnvMode::Replace));
    // Texel for pixel.
    textured_quad(r, [0.0, 0.0, tw as f32, th as f32], [0.0, 0.0, 1.0, 1.0]);
    // Magnified, NEAREST, part of the texture, rotated by 20 degrees.
    let (w, h) = (s.wf(), s.hf());
    r.call(Call::PushMatrix)
        .translate(w * 0.7, h * 0.3, 0.0)
        .call(Call::Rotate(20.0, [0.0, 0.0, 1.0]));
    textured_quad(r, [-w * 0.25, -h * 0.2, w * 0.25, h * 0.2], [0.1, 0.2, 0.9, 0.8]);
    r.call(Call::PopMatrix);
    // Magnified, LINEAR.
    r.tex_parameter(T2, TexParam::MagFilter(Filter::Linear));
    textured_quad(r, [0.0, h * 0.55, w * 0.5, h], [0.0, 0.0, 1.0, 1.0]);
    r.disable(Capability::Texture(T2));
}

/// As [`render_to_texture`] into a 64×64 texture, then `glGenerateMipmap`
/// and the texture minified with LINEAR_MIPMAP_LINEAR and NEAREST_MIPMAP_NEAREST.
fn render_to_texture_mipmaps(r: &mut Rec, s: Size) {
    let t = 64;
    empty_texture(r, 3, t, t, (Filter::Linear, MipFilter::Linear), Filter::Linear);
    r.call(Call::BindFramebuffer(BOTH, 3)).call(Call::FramebufferTexture2D(
        BOTH,
        AttachmentPoint::Color(0),
        TexImageTarget::D2,
        3,
        0,
    ));
    pixel_view(r, t as u32, t as u32);
    r.clear(ClearMask::COLOR);
    gradient_background(
        r,
        Size {
            w: t as u32,
            h: t as u32,
            full: s.full,
        },
    );
    random_triangles(
        r,
        &mut Rng::new(301),
        40,
        Size {
            w: t as u32,
            h: t as u32,
            full: true,
        },
        10.0,
        (1.0, 1.0),
    );
    r.call(Call::BindFramebuffer(BOTH, 0)).call(Call::GenerateMipmap(T2));
    pixel_view(r, s.w, s.h);
    r.enable(Capability::Texture(T2))
        .tex_env(TexEnvParam::Mode(EnvMode::Replace));
    let (w, h) = (s.wf(), s.hf());
    // Sizes that pick levels 1..4 and between them.
    let mut x = 0.0;
    for (i, k) in [0.5f32, 0.37, 0.25, 0.18, 0.125, 0.09].into_iter().enumerate() {
        let side = t as f32 * k * w / 96.0;
        textured_quad(r, [x, 0.0, x + side, side], [0.0, 0.0, 1.0, 1.0]);
        if i == 2 {
            r.tex_parameter(T2, TexParam::MinFilter(Filter::Nearest, MipFilter::Nearest));
        }
        x += side + 1.0;
    }
    r.tex_parameter(T2, TexParam::MinFilter(Filter::Linear, MipFilter::Linear));
    // A receding plane: every level at once.
    r.begin(PrimitiveMode::TriangleStrip)
        .tex_coord(0.0, 0.0)
        .vertex(0.0, h * 0.45, 0.0)
        .tex_coord(4.0, 0.0)
        .vertex(w, h * 0.45, 0.0);
    r.call(Call::TexCoord(0, [0.0, 4.0 * 0.1, 0.0, 0.1]))
        .vertex4(w * 0.45 * 0.1, h * 0.1, 0.0, 0.1)
        .call(Call::TexCoord(0, [4.0 * 0.1, 4.0 * 0.1, 0.0, 0.1]))
        .vertex4(w * 0.55 * 0.1, h * 0.1, 0.0, 0.1)
        .end();
    r.disable(Capability::Texture(T2));
}

/// A 48×40 object (renderbuffers) blitted to the window: 1:1, magnified
/// NEAREST and LINEAR by non-integer factors, minified LINEAR and NEAREST,
/// and a part of it magnified.
fn blit_color(r: &mut Rec, s: Size) {
    let (fw, fh) = (48, 40);
    renderbuffer_fbo(r, 1, 1, 2, [fw, fh], 0);
    pixel_view(r, fw as u32, fh as u32);
    content(r, fw as u32, fh as u32, true, 302, 40);
    bind_read_draw(r, 1, 0);
    let (w, h) = (s.w as i32, s.h as i32);
    let src = [0, 0, fw, fh];
    use BlitFilter::{Linear, Nearest};
    blit(r, src, [0, 0, fw, fh], COLOR, Nearest);
    blit(r, src, [fw, 0, w, h / 2], COLOR, Nearest);
    blit(r, src, [0, h / 2, w / 2, h], COLOR, Linear);
    // Minified LINEAR and NEAREST, and a part magnified.
    blit(r, src, [2, h / 2 - 12, 2 + 17, h / 2 - 1], COLOR, Linear);
    blit(r, [10, 7, 23, 19], [w * 3 / 4, 0, w, h / 4], COLOR, Linear);
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Depth and stencil rendered into an object the window's size, blitted to
/// the window (all of it 1:1, then a part magnified NEAREST), and shown:
/// depth as bands of colour (quads at rising depths, LESS, mask off),
/// stencil by [`show_stencil`].
fn blit_depth_stencil(r: &mut Rec, s: Size) {
    let (w, h) = (s.w as i32, s.h as i32);
    renderbuffer_fbo(r, 1, 1, 2, [w, h], 0);
    pixel_view(r, s.w, s.h);
    r.call(Call::ClearDepth(1.0)).clear(ClearMask::ALL);
    r.enable(Capability::DepthTest)
        .enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 0, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Incr, StencilOp::Incr));
    random_triangles(r, &mut Rng::new(303), s.count(200), s, 16.0, (1.0, 1.0));
    r.disable(Capability::DepthTest).disable(Capability::StencilTest);
    bind_read_draw(r, 1, 0);
    let ds = BlitMask {
        color: false,
        depth: true,
        stencil: true,
    };
    blit(r, [0, 0, w, h], [0, 0, w, h], ds, BlitFilter::Nearest);
    blit(
        r,
        [w / 4, h / 4, w / 2, h / 2],
        [w / 2, 0, w, h / 2],
        ds,
        BlitFilter::Nearest,
    );
    r.call(Call::BindFramebuffer(BOTH, 0));
    show_depth_bands(r, s, 24);
    r.call(Call::ColorMask([true, false, true, true]));
    show_stencil(r, s, &[1, 2, 3, 4, 5, 6]);
    r.call(Call::ColorMask([true; 4])).disable(Capability::StencilTest);
}

/// Full-window quads at `n` rising depths drawn with LESS and the depth mask
/// off: each pixel shows the band its depth lies in.
pub fn show_depth_bands(r: &mut Rec, s: Size, n: usize) {
    r.clear(ClearMask::COLOR)
        .enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Less))
        .call(Call::DepthMask(false));
    for i in 0..n {
        let depth = i as f32 / n as f32;
        // Window depth (1 - z) / 2 under glOrtho(…, -1, 1).
        let z = 1.0 - 2.0 * depth;
        r.color(depth, 1.0 - depth, (i % 3) as f32 / 2.0, 1.0)
            .rect(0.0, 0.0, s.wf(), s.hf(), z);
    }
    r.call(Call::DepthMask(true)).disable(Capability::DepthTest);
}

/// 4× renderbuffers (colour, depth-stencil) drawn with depth-tested
/// triangles, resolved by a blit into a single-sampled object,
/// which is blitted to the window; a part resolved straight to the window.
fn msaa_resolve(r: &mut Rec, s: Size) {
    let (w, h) = (s.w as i32, s.h as i32);
    renderbuffer_fbo(r, 1, 1, 2, [w, h], 4);
    renderbuffer_fbo(r, 2, 3, 4, [w, h], 0);
    r.call(Call::BindFramebuffer(BOTH, 1));
    pixel_view(r, s.w, s.h);
    content(r, s.w, s.h, s.full, 304, 300);
    bind_read_draw(r, 1, 2);
    blit(r, [0, 0, w, h], [0, 0, w, h], COLOR, BlitFilter::Nearest);
    bind_read_draw(r, 2, 0);
    blit(r, [0, 0, w, h], [0, 0, w, h], COLOR, BlitFilter::Nearest);
    bind_read_draw(r, 1, 0);
    blit(
        r,
        [w / 3, h / 3, w * 2 / 3, h * 2 / 3],
        [w / 3, h / 3, w * 2 / 3, h * 2 / 3],
        COLOR,
        BlitFilter::Linear,
    );
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Lines 2 pixels wide, depth-tested, into a 4× object, resolved to the window.
fn msaa_lines(r: &mut Rec, s: Size) {
    let (w, h) = (s.w as i32, s.h as i32);
    renderbuffer_fbo(r, 1, 1, 2, [w, h], 4);
    pixel_view(r, s.w, s.h);
    r.clear(ClearMask::ALL);
    let mut rng = Rng::new(305);
    r.enable(Capability::DepthTest).call(Call::LineWidth(2.0));
    r.begin(PrimitiveMode::Lines);
    for _ in 0..s.count(80) {
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .vertex(rng.range(0.0, s.wf()), rng.range(0.0, s.hf()), rng.range(-1.0, 1.0))
            .vertex(rng.range(0.0, s.wf()), rng.range(0.0, s.hf()), rng.range(-1.0, 1.0));
    }
    r.end();
    r.call(Call::LineWidth(1.0)).disable(Capability::DepthTest);
    bind_read_draw(r, 1, 0);
    blit(r, [0, 0, w, h], [0, 0, w, h], COLOR, BlitFilter::Nearest);
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Blits reversed: the destination in x, the source in y, both, one
/// reversed running off the window's right edge, one with the source
/// running off the object; and a minified NEAREST blit.
fn blit_flipped(r: &mut Rec, s: Size) {
    let (fw, fh) = (48, 40);
    renderbuffer_fbo(r, 1, 1, 2, [fw, fh], 0);
    pixel_view(r, fw as u32, fh as u32);
    content(r, fw as u32, fh as u32, true, 302, 40);
    bind_read_draw(r, 1, 0);
    let (w, h) = (s.w as i32, s.h as i32);
    let src = [0, 0, fw, fh];
    use BlitFilter::{Linear, Nearest};
    blit(r, src, [w - 1, h - 1, w / 2 + 3, h / 2 + 5], COLOR, Nearest);
    blit(r, [0, fh, fw, 0], [w / 2, h / 2, w * 3 / 4, h * 3 / 4], COLOR, Linear);
    blit(r, [fw, fh, 0, 0], [w / 2 + 2, 2, w * 2 / 3, h / 5], COLOR, Linear);
    blit(r, [fw, 0, 0, fh], [w + 20, 2, w * 2 / 3 + 2, h / 3], COLOR, Nearest);
    blit(r, src, [fw, fh, 0, 0], COLOR, Nearest);
    blit(
        r,
        [-5, fh + 7, fw + 3, -9],
        [w / 3, h / 2, w / 2 + 5, h * 3 / 4],
        COLOR,
        Linear,
    );
    // Minified NEAREST (not reversed).
    blit(r, src, [22, h / 2 - 12, 22 + 17, h / 2 - 1], COLOR, Nearest);
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Writes query `q`'s count into a `size`×`size` block at `(x, y)` (a
/// scissored clear; the scissor is left on).
pub fn show_query(r: &mut Rec, q: u32, x: i32, y: i32, size: i32) {
    r.enable(Capability::ScissorTest)
        .scissor(x, y, size, size)
        .call(Call::ClearColorFromQuery(q))
        .clear(ClearMask::COLOR);
}

/// Queries around: a full quad; depth-tested triangles, half hidden; a
/// stencil test passing a part; the alpha test; a scissored draw; colour
/// writes off (still counted); lines and points. Each count is shown as a
/// block of colour along the bottom row.
fn occlusion_counts(r: &mut Rec, s: Size) {
    let (w, h) = (s.wf(), s.hf());
    let mut rng = Rng::new(306);
    r.call(Call::BeginQuery(1)).color(0.3, 0.3, 0.3, 1.0);
    r.rect(0.0, 0.0, w, h, 0.5);
    r.call(Call::EndQuery);
    r.enable(Capability::DepthTest).call(Call::DepthFunc(CompareFunc::Less));
    r.call(Call::BeginQuery(2));
    random_triangles(r, &mut rng, s.count(200), s, 14.0, (1.0, 1.0));
    r.call(Call::EndQuery);
    // Stencil: the first triangles write 1, the query counts those drawn over them.
    r.enable(Capability::StencilTest)
        .call(Call::StencilFunc(CompareFunc::Always, 1, 0xff))
        .call(Call::StencilOp(StencilOp::Keep, StencilOp::Keep, StencilOp::Replace))
        .call(Call::DepthFunc(CompareFunc::Always));
    random_triangles(r, &mut rng, s.count(80), s, 14.0, (1.0, 1.0));
    r.call(Call::StencilFunc(CompareFunc::Equal, 1, 0xff))
        .call(Call::BeginQuery(3));
    random_triangles(r, &mut rng, s.count(80), s, 14.0, (1.0, 1.0));
    r.call(Call::EndQuery).disable(Capability::StencilTest);
    // The alpha test.
    r.enable(Capability::AlphaTest)
        .call(Call::AlphaFunc(CompareFunc::Greater, 0.5))
        .call(Call::BeginQuery(4));
    random_triangles(r, &mut rng, s.count(80), s, 14.0, (0.0, 1.0));
    r.call(Call::EndQuery).disable(Capability::AlphaTest);
    // Scissored, and colour writes off.
    r.enable(Capability::ScissorTest)
        .scissor(s.w as i32 / 5, s.h as i32 / 3, s.w as i32 / 2, s.h as i32 / 2)
        .call(Call::BeginQuery(5));
    random_triangles(r, &mut rng, s.count(80), s, 14.0, (1.0, 1.0));
    r.call(Call::EndQuery).disable(Capability::ScissorTest);
    r.call(Call::ColorMask([false; 4])).call(Call::BeginQuery(6));
    random_triangles(r, &mut rng, s.count(80), s, 14.0, (1.0, 1.0));
    r.call(Call::EndQuery).call(Call::ColorMask([true; 4]));
    // Lines and points, depth LEQUAL.
    r.call(Call::DepthFunc(CompareFunc::Lequal)).call(Call::BeginQuery(7));
    r.begin(PrimitiveMode::Lines);
    for _ in 0..s.count(60) {
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0)
            .vertex(rng.range(0.0, w), rng.range(0.0, h), rng.range(-1.0, 1.0))
            .vertex(rng.range(0.0, w), rng.range(0.0, h), rng.range(-1.0, 1.0));
    }
    r.end().call(Call::PointSize(3.0)).begin(PrimitiveMode::Points);
    for _ in 0..s.count(60) {
        r.color(rng.unit(), rng.unit(), rng.unit(), 1.0).vertex(
            rng.range(0.0, w),
            rng.range(0.0, h),
            rng.range(-1.0, 1.0),
        );
    }
    r.end().call(Call::PointSize(1.0)).call(Call::EndQuery);
    r.disable(Capability::DepthTest);
    // A query begun again counts from zero.
    r.call(Call::BeginQuery(8)).color(0.8, 0.1, 0.1, 1.0);
    r.rect(w * 0.25, h * 0.25, w * 0.5, h * 0.5, 0.0);
    r.call(Call::EndQuery).call(Call::BeginQuery(8));
    r.rect(w * 0.5, h * 0.5, w * 0.55, h * 0.6, 0.0);
    r.call(Call::EndQuery);
    for q in 1..=8 {
        show_query(r, q, (q as i32 - 1) * 6, 0, 6);
    }
    r.disable(Capability::ScissorTest).scissor(0, 0, s.w as i32, s.h as i32);
}

/// Queries around draws into a 4× object count samples: a full quad (4 a
/// pixel) and triangles (edge pixels count 1..3).
fn occlusion_msaa(r: &mut Rec, s: Size) {
    let (w, h) = (s.w as i32, s.h as i32);
    renderbuffer_fbo(r, 1, 1, 2, [w, h], 4);
    pixel_view(r, s.w, s.h);
    r.clear(ClearMask::ALL);
    r.call(Call::BeginQuery(1)).color(0.2, 0.4, 0.6, 1.0);
    r.rect(0.0, 0.0, s.wf() / 2.0, s.hf(), 0.0);
    r.call(Call::EndQuery);
    r.enable(Capability::DepthTest).call(Call::BeginQuery(2));
    random_triangles(r, &mut Rng::new(307), s.count(120), s, 12.0, (1.0, 1.0));
    r.call(Call::EndQuery).disable(Capability::DepthTest);
    bind_read_draw(r, 1, 0);
    blit(r, [0, 0, w, h], [0, 0, w, h], COLOR, BlitFilter::Nearest);
    r.call(Call::BindFramebuffer(BOTH, 0));
    for q in 1..=2 {
        show_query(r, q, (q as i32 - 1) * 8, 0, 8);
    }
    r.disable(Capability::ScissorTest).scissor(0, 0, w, h);
}

/// A 1×1 object: cleared, drawn into (a triangle over its centre, one
/// missing it), blitted to the window NEAREST and LINEAR, magnified.
fn fbo_1x1(r: &mut Rec, s: Size) {
    renderbuffer_fbo(r, 1, 1, 2, [1, 1], 0);
    pixel_view(r, 1, 1);
    r.clear_color(0.1, 0.2, 0.3, 0.4).clear(ClearMask::ALL);
    r.begin(PrimitiveMode::Triangles)
        .color(1.0, 0.5, 0.0, 1.0)
        .vertex(0.25, 0.25, 0.0)
        .vertex(0.9, 0.5, 0.0)
        .vertex(0.5, 0.9, 0.0)
        .color(0.0, 1.0, 0.0, 1.0)
        .vertex(0.6, 0.6, 0.0)
        .vertex(0.9, 0.6, 0.0)
        .vertex(0.6, 0.9, 0.0)
        .end();
    bind_read_draw(r, 1, 0);
    let (w, h) = (s.w as i32, s.h as i32);
    blit(r, [0, 0, 1, 1], [0, 0, w / 2, h], COLOR, BlitFilter::Nearest);
    blit(r, [0, 0, 1, 1], [w / 2, 0, w, h / 2], COLOR, BlitFilter::Linear);
    blit(r, [1, 1, 0, 0], [w / 2, h / 2, w - 3, h - 3], COLOR, BlitFilter::Linear);
    r.call(Call::BindFramebuffer(BOTH, 0));
    r.clear_color(0.0, 0.0, 0.0, 0.0);
}

/// An 8192×8192 object (renderbuffers: 256 MiB of colour, as much of
/// depth-stencil): cleared, drawn across, scissor-cleared at its far
/// corners, and blitted to the window whole (NEAREST, minified) and its far
/// corner 1:1.
fn fbo_8192(r: &mut Rec, s: Size) {
    let n = 8192;
    renderbuffer_fbo(r, 1, 1, 2, [n, n], 0);
    pixel_view(r, n as u32, n as u32);
    r.clear_color(0.2, 0.1, 0.3, 1.0).clear(ClearMask::ALL);
    // Few, large triangles: the object's size is the point, not its fill rate.
    let big = Size {
        w: n as u32,
        h: n as u32,
        full: true,
    };
    r.enable(Capability::DepthTest);
    random_triangles(r, &mut Rng::new(308), 12, big, 1500.0, (1.0, 1.0));
    r.disable(Capability::DepthTest);
    r.enable(Capability::ScissorTest)
        .scissor(n - 40, n - 40, 40, 40)
        .clear_color(1.0, 1.0, 0.0, 1.0)
        .clear(ClearMask::COLOR)
        .scissor(0, 0, 40, 40)
        .clear_color(0.0, 1.0, 1.0, 1.0)
        .clear(ClearMask::COLOR)
        .disable(Capability::ScissorTest)
        .clear_color(0.0, 0.0, 0.0, 0.0);
    bind_read_draw(r, 1, 0);
    let (w, h) = (s.w as i32, s.h as i32);
    // Two blits only: each copies the whole 8192x8192 source today (see the report).
    blit(r, [0, 0, n, n], [0, 0, w / 2, h / 2], COLOR, BlitFilter::Nearest);
    blit(
        r,
        [n - 60, n - 60, n, n],
        [w / 2, h / 2, w / 2 + 60, h / 2 + 60],
        COLOR,
        BlitFilter::Nearest,
    );
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Blits whose rectangles run off both buffers (negative coordinates, past
/// the far edges), reversed in one or both axes, empty, and entirely
/// outside: the clipped parts must scale as the unclipped would.
fn blit_negative_extents(r: &mut Rec, s: Size) {
    let (fw, fh) = (40, 32);
    renderbuffer_fbo(r, 1, 1, 2, [fw, fh], 0);
    pixel_view(r, fw as u32, fh as u32);
    content(r, fw as u32, fh as u32, true, 309, 30);
    bind_read_draw(r, 1, 0);
    let (w, h) = (s.w as i32, s.h as i32);
    use BlitFilter::{Linear, Nearest};
    blit(r, [-20, -10, fw + 20, fh + 10], [0, 0, w / 2, h / 2], COLOR, Nearest);
    blit(r, [-20, -10, fw + 20, fh + 10], [w / 2, 0, w, h / 2], COLOR, Linear);
    blit(r, [0, 0, fw, fh], [-30, h / 2, w / 3, h + 25], COLOR, Nearest);
    // Empty and outside: nothing.
    blit(r, [5, 5, 5, 20], [0, 0, w, h], COLOR, Nearest);
    blit(r, [0, 0, fw, fh], [10, 10, 10, 40], COLOR, Nearest);
    blit(r, [-100, -100, -50, -50], [0, 0, w, h], COLOR, Nearest);
    blit(r, [0, 0, fw, fh], [-1000, -1000, -10, -10], COLOR, Linear);
    blit(r, [0, 0, fw, fh], [w + 10, 0, w + 100, h], COLOR, Linear);
    r.call(Call::BindFramebuffer(BOTH, 0));
}

/// Queries around nothing: no draw at all, a triangle outside the view, a
/// quad the alpha test rejects, depth NEVER, a zero-area triangle, a
/// scissor box of zero size, and one query begun and ended with a draw
/// that passes only after it. Each count (all zero) is shown as a block.
fn query_zero_fragments(r: &mut Rec, s: Size) {
    let (w, h) = (s.wf(), s.hf());
    r.color(0.5, 0.5, 0.5, 1.0);
    r.call(Call::BeginQuery(1)).call(Call::EndQuery);
    r.call(Call::BeginQuery(2));
    r.rect(-50.0, -50.0, -10.0, -10.0, 0.0);
    r.rect(0.0, 0.0, w, h, 5.0);
    r.call(Call::EndQuery);
    r.enable(Capability::AlphaTest)
        .call(Call::AlphaFunc(CompareFunc::Never, 0.0))
        .call(Call::BeginQuery(3));
    r.rect(0.0, 0.0, w, h, 0.0);
    r.call(Call::EndQuery).disable(Capability::AlphaTest);
    r.enable(Capability::DepthTest)
        .call(Call::DepthFunc(CompareFunc::Never))
        .call(Call::BeginQuery(4));
    r.rect(0.0, 0.0, w, h, 0.0);
    r.call(Call::EndQuery).disable(Capability::DepthTest);
    r.call(Call::BeginQuery(5))
        .begin(PrimitiveMode::Triangles)
        .vertex(10.0, 10.0, 0.0)
        .vertex(20.0, 20.0, 0.0)
        .vertex(30.0, 30.0, 0.0)
        .end()
        .call(Call::EndQuery);
    r.enable(Capability::ScissorTest)
        .scissor(10, 10, 0, 0)
        .call(Call::BeginQuery(6));
    r.rect(0.0, 0.0, w, h, 0.0);
    r.call(Call::EndQuery).disable(Capability::ScissorTest);
    r.call(Call::BeginQuery(7)).call(Call::EndQuery);
    r.color(0.2, 0.8, 0.2, 1.0).rect(0.0, h * 0.5, w, h, 0.0);
    for q in 1..=7 {
        show_query(r, q, (q as i32 - 1) * 6 + 1, 1, 5);
    }
    r.disable(Capability::ScissorTest).scissor(0, 0, s.w as i32, s.h as i32);
}
