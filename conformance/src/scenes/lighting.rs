//! Lighting, materials and user clip planes (GL 1.5 §2.11, §2.14), issue 11:
//! GLU-style lit spheres smooth and flat, eight mixed lights, two-sided
//! lighting on a twisted strip, a local viewer, colour material, separate
//! specular, clip planes cutting a lit mesh, lighting with fog, and the stiff
//! cases (shininess 0 and 128, spot exponent 128, normals of length 1e-20 and
//! 1e20 with and without `GL_NORMALIZE`).

use super::{Group, Scene, Size, Tolerance};
use crate::call::{Call, Rec};
use softgl::{
    Capability, ColorControl, ColorMaterialMode, Face, FogMode, FogParam, LightModelParam, LightParam, MaterialParam,
    MatrixMode, PrimitiveMode, ShadeModel,
};

const G: Group = Group::Lighting;

/// Measured 2026-11-23: identical to llvmpipe at 96x96 and 256x256 (softpipe
/// differs on 1..5 pixels of each).
const E: Tolerance = Tolerance {
    reason: "softgl lights vertices with llvmpipe's f32 operation order, pow, exp2 and log2 \
             (docs/llvmpipe-facts.md 15) and interpolates as llvmpipe does",
    ..Tolerance::EXACT
};

/// Measured 2026-11-23: colours 1 LSB off llvmpipe's on `test` pixels at
/// 96x96 and `report` at 256x256, none further; softpipe is off on as many or
/// more (1..5) in each of these scenes.
const fn lsb(test: usize, report: usize) -> Tolerance {
    Tolerance::lsb(
        test,
        report,
        "1 LSB on the pixels counted, where a lit colour's last f32 bit differs from llvmpipe's \
         (cause not identified yet; what softgl copies of Mesa's vertex arithmetic: docs/llvmpipe-facts.md \
         §15); softpipe as far or farther",
    )
}

pub fn scenes() -> Vec<Scene> {
    vec![
        Scene::new("lit_sphere_smooth", G, lsb(0, 1), |r, s| {
            lit_spheres(r, s, ShadeModel::Smooth)
        }),
        Scene::new("lit_sphere_flat", G, E, |r, s| lit_spheres(r, s, ShadeModel::Flat)),
        Scene::new("eight_lights_spot_attenuation", G, lsb(1, 1), eight_lights),
        Scene::new("two_sided_twisted_strip", G, E, two_sided),
        Scene::new("local_viewer", G, lsb(1, 0), local_viewer),
        Scene::new("color_material", G, lsb(0, 1), color_material),
        Scene::new("separate_specular", G, lsb(0, 3), separate_specular),
        Scene::new("clip_planes_lit_mesh", G, E, clip_planes),
        Scene::new("lit_fog_exp", G, E, lit_fog),
        Scene::new("shininess_0_and_128", G, E, shininess),
        Scene::new("spot_exponent_128", G, E, spot_exponent),
        // The 1e-20 normals under GL_NORMALIZE become infinite as in llvmpipe,
        // whose vertex stage flushes denormals (docs/llvmpipe-facts.md,
        // "Denormals in the vertex stage"). Measured 2026-11-23: identical at
        // 256x256, 2 pixels 1 LSB off at 96x96 (softpipe: 2 and 2).
        Scene::new("normal_lengths", G, lsb(2, 0), normal_lengths),
    ]
}

/// A perspective view (near 2, far 30) looking down -z, depth test on,
/// lighting on with GL's default light model.
pub(super) fn lit_view(r: &mut Rec) {
    r.matrix_mode(MatrixMode::Projection)
        .load_identity()
        .frustum(-1.0, 1.0, -1.0, 1.0, 2.0, 30.0)
        .matrix_mode(MatrixMode::Modelview)
        .load_identity()
        .enable(Capability::DepthTest)
        .enable(Capability::Lighting);
}

/// GLU's `gluSphere` (`GLU_SMOOTH` normals, quad strips from the south
/// pole up) centred at `c`, its normals scaled by `normal_scale`.
fn sphere(r: &mut Rec, c: [f32; 3], radius: f32, (slices, stacks): (u32, u32), normal_scale: f32) {
    sphere_with(r, c, radius, (slices, stacks), normal_scale, SphereTex::None);
}

/// The texture coordinates [`sphere_with`] gives each vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SphereTex {
    None,
    /// GLU's (`gluQuadricTexture`): s = slice / slices, t = stack / stacks.
    Glu,
    /// The unit normal as (s, t, r), for cube maps.
    Normal,
}

/// [`sphere`], with texture coordinates `tex`.
pub(super) fn sphere_with(
    r: &mut Rec,
    c: [f32; 3],
    radius: f32,
    (slices, stacks): (u32, u32),
    normal_scale: f32,
    tex: SphereTex,
) {
    use std::f32::consts::PI;
    let point = |i: u32, j: u32| {
        let (theta, phi) = (2.0 * PI * i as f32 / slices as f32, PI * j as f32 / stacks as f32);
        let (st, ct, sp, cp) = (theta.sin(), theta.cos(), phi.sin(), phi.cos());
        [-st * sp, ct * sp, cp]
    };
    for j in 0..stacks {
        r.begin(PrimitiveMode::QuadStrip);
        for i in 0..=slices {
            for jj in [j, j + 1] {
                let n = point(i % slices, jj);
                match tex {
                    SphereTex::None => {}
                    SphereTex::Glu => {
                        r.tex_coord(i as f32 / slices as f32, jj as f32 / stacks as f32);
                    }
                    SphereTex::Normal => {
                        r.call(Call::TexCoord(0, [n[0], n[1], n[2], 1.0]));
                    }
                }
                r.normal(n[0] * normal_scale, n[1] * normal_scale, n[2] * normal_scale);
                r.vertex(c[0] + radius * n[0], c[1] + radius * n[1], c[2] + radius * n[2]);
            }
        }
        r.end();
    }
}

/// A white material with a tinted specular and `shininess`.
pub(super) fn material(r: &mut Rec, diffuse: [f32; 4], shininess: f32) {
    r.material(Face::FrontAndBack, MaterialParam::Ambient([0.2, 0.2, 0.25, 1.0]))
        .material(Face::FrontAndBack, MaterialParam::Diffuse(diffuse))
        .material(Face::FrontAndBack, MaterialParam::Specular([0.9, 0.9, 0.7, 1.0]))
        .material(Face::FrontAndBack, MaterialParam::Shininess(shininess));
}

/// Light `i` on: directional from `dir` (w = 0) or positional, white.
pub(super) fn light(r: &mut Rec, i: u8, position: [f32; 4], diffuse: [f32; 4]) {
    r.enable(Capability::Light(i))
        .light(u32::from(i), LightParam::Position(position))
        .light(u32::from(i), LightParam::Diffuse(diffuse))
        .light(u32::from(i), LightParam::Specular([1.0, 1.0, 1.0, 1.0]));
}

/// Four spheres (tessellations 24x16 and 9x6) under one directional light.
fn lit_spheres(r: &mut Rec, _s: Size, shade: ShadeModel) {
    lit_view(r);
    r.shade_model(shade);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.8, 0.3, 0.2, 1.0], 32.0);
    sphere(r, [-2.2, 2.2, -9.0], 2.0, (24, 16), 1.0);
    sphere(r, [2.2, 2.2, -9.0], 2.0, (9, 6), 1.0);
    material(r, [0.2, 0.5, 0.9, 1.0], 8.0);
    sphere(r, [-2.2, -2.2, -9.0], 2.0, (24, 16), 1.0);
    sphere(r, [2.2, -2.2, -9.0], 2.0, (9, 6), 1.0);
}

/// Eight lights: two directional, three positional with constant, linear
/// and quadratic attenuation, three spotlights of different cutoffs and
/// exponents; ambient light per light too.
fn eight_lights(r: &mut Rec, _s: Size) {
    lit_view(r);
    let colors = [
        [1.0, 0.2, 0.2, 1.0],
        [0.2, 1.0, 0.2, 1.0],
        [0.2, 0.2, 1.0, 1.0],
        [1.0, 1.0, 0.2, 1.0],
        [0.2, 1.0, 1.0, 1.0],
        [1.0, 0.2, 1.0, 1.0],
        [0.8, 0.8, 0.8, 1.0],
        [1.0, 0.6, 0.2, 1.0],
    ];
    let positions = [
        [1.0, 0.0, 0.5, 0.0],
        [-0.5, 1.0, 0.3, 0.0],
        [-3.0, -2.0, -4.0, 1.0],
        [3.0, 2.0, -5.0, 1.0],
        [0.0, -3.0, -6.0, 1.0],
        [-2.0, 2.0, -3.0, 1.0],
        [2.0, -2.0, -3.0, 1.0],
        [0.0, 0.0, -2.5, 1.0],
    ];
    for (i, (p, c)) in positions.iter().zip(colors).enumerate() {
        light(r, i as u8, *p, [c[0] * 0.6, c[1] * 0.6, c[2] * 0.6, 1.0]);
        r.light(
            i as u32,
            LightParam::Ambient([c[0] * 0.05, c[1] * 0.05, c[2] * 0.05, 1.0]),
        );
    }
    r.light(2, LightParam::ConstantAttenuation(0.5))
        .light(3, LightParam::LinearAttenuation(0.2))
        .light(4, LightParam::QuadraticAttenuation(0.05))
        .light(5, LightParam::SpotDirection([0.6, -0.6, -1.0]))
        .light(5, LightParam::SpotCutoff(30.0))
        .light(5, LightParam::SpotExponent(4.0))
        .light(6, LightParam::SpotDirection([-0.5, 0.5, -1.0]))
        .light(6, LightParam::SpotCutoff(45.0))
        .light(6, LightParam::LinearAttenuation(0.1))
        .light(7, LightParam::SpotDirection([0.0, 0.0, -1.0]))
        .light(7, LightParam::SpotCutoff(20.0))
        .light(7, LightParam::SpotExponent(16.0));
    material(r, [0.9, 0.9, 0.9, 1.0], 20.0);
    sphere(r, [0.0, 0.0, -10.0], 4.0, (32, 24), 1.0);
    // A floor behind it, finely tessellated so the spots show.
    grid(r, 16, (-12.0, 1.5), -16.0);
}

/// An `n` x `n` grid of triangle strips facing +z at depth `z`, from
/// `(start, start)` in steps of `step`.
fn grid(r: &mut Rec, n: u32, (start, step): (f32, f32), z: f32) {
    r.normal(0.0, 0.0, 1.0);
    for j in 0..n {
        r.begin(PrimitiveMode::TriangleStrip);
        for i in 0..=n {
            for jj in [j, j + 1] {
                r.vertex(start + step * i as f32, start + step * jj as f32, z);
            }
        }
        r.end();
    }
}

/// Two-sided lighting with distinct front and back materials on a strip
/// twisted half a turn, so both faces show; a second strip flat-shaded.
fn two_sided(r: &mut Rec, _s: Size) {
    lit_view(r);
    r.light_model(LightModelParam::TwoSide(true));
    light(r, 0, [0.3, 0.5, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    light(r, 1, [-2.0, -1.0, -4.0, 1.0], [0.5, 0.5, 0.9, 1.0]);
    r.material(Face::Front, MaterialParam::Diffuse([0.9, 0.4, 0.1, 1.0]))
        .material(Face::Back, MaterialParam::Diffuse([0.1, 0.5, 0.9, 1.0]))
        .material(Face::Back, MaterialParam::Specular([0.3, 1.0, 0.3, 1.0]))
        .material(Face::Back, MaterialParam::Shininess(64.0))
        .material(Face::Front, MaterialParam::Specular([1.0, 1.0, 1.0, 1.0]))
        .material(Face::Front, MaterialParam::Shininess(10.0));
    for (y, shade) in [(1.8, ShadeModel::Smooth), (-1.8, ShadeModel::Flat)] {
        r.shade_model(shade).begin(PrimitiveMode::QuadStrip);
        for i in 0..=24 {
            let t = i as f32 / 24.0;
            let a = std::f32::consts::PI * t;
            let x = -5.0 + 10.0 * t;
            let (c, s) = (a.cos(), a.sin());
            r.normal(0.0, -s, c);
            r.vertex(x, y + 1.4 * c, -9.0 + 1.4 * s);
            r.vertex(x, y - 1.4 * c, -9.0 - 1.4 * s);
        }
        r.end();
    }
}

/// A positional light close to a shiny sphere and plane, with and without
/// `GL_LIGHT_MODEL_LOCAL_VIEWER` side by side.
fn local_viewer(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.0, 3.0, -4.0, 1.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.5, 0.5, 0.6, 1.0], 60.0);
    r.light_model(LightModelParam::LocalViewer(true));
    sphere(r, [-2.2, 0.0, -8.0], 2.0, (24, 16), 1.0);
    r.light_model(LightModelParam::LocalViewer(false));
    sphere(r, [2.2, 0.0, -8.0], 2.0, (24, 16), 1.0);
}

/// `glColorMaterial` in each mode, per-vertex colours on four spheres.
fn color_material(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    r.light(0, LightParam::Ambient([0.3, 0.3, 0.3, 1.0]));
    material(r, [0.6, 0.6, 0.6, 1.0], 16.0);
    r.enable(Capability::ColorMaterial);
    let modes = [
        ColorMaterialMode::AmbientAndDiffuse,
        ColorMaterialMode::Diffuse,
        ColorMaterialMode::Specular,
        ColorMaterialMode::Emission,
    ];
    for (k, mode) in modes.into_iter().enumerate() {
        r.call(Call::ColorMaterial(Face::FrontAndBack, mode));
        let c = [-2.2 + 4.4 * (k % 2) as f32, 2.2 - 4.4 * (k / 2) as f32, -9.0];
        // The colour changes per stack: colour material follows glColor.
        sphere_colored(r, c, 2.0, k);
    }
    // Restore the materials colour material overwrote, for the next frame.
    r.disable(Capability::ColorMaterial);
}

/// [`sphere`] with a colour per stack.
fn sphere_colored(r: &mut Rec, c: [f32; 3], radius: f32, seed: usize) {
    use std::f32::consts::PI;
    let (slices, stacks) = (20u32, 12u32);
    for j in 0..stacks {
        let t = (j as f32 + seed as f32) / stacks as f32;
        r.color(0.3 + 0.7 * t, 0.9 - 0.6 * t, 0.2 + 0.5 * (1.0 - t), 1.0);
        r.begin(PrimitiveMode::QuadStrip);
        for i in 0..=slices {
            for jj in [j, j + 1] {
                let (theta, phi) = (
                    2.0 * PI * (i % slices) as f32 / slices as f32,
                    PI * jj as f32 / stacks as f32,
                );
                let n = [-theta.sin() * phi.sin(), theta.cos() * phi.sin(), phi.cos()];
                r.normal(n[0], n[1], n[2]);
                r.vertex(c[0] + radius * n[0], c[1] + radius * n[1], c[2] + radius * n[2]);
            }
        }
        r.end();
    }
}

/// `GL_SEPARATE_SPECULAR_COLOR` against `GL_SINGLE_COLOR` on bright spheres
/// (the sum saturates differently).
fn separate_specular(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.2, 0.4, 1.0, 0.0], [1.0, 0.9, 0.8, 1.0]);
    light(r, 1, [2.0, 3.0, -3.0, 1.0], [0.4, 0.4, 1.0, 1.0]);
    material(r, [0.7, 0.5, 0.3, 1.0], 24.0);
    r.light_model(LightModelParam::ColorControl(ColorControl::SeparateSpecular));
    sphere(r, [-2.2, 0.0, -8.0], 2.0, (24, 16), 1.0);
    r.light_model(LightModelParam::ColorControl(ColorControl::SingleColor));
    sphere(r, [2.2, 0.0, -8.0], 2.0, (24, 16), 1.0);
}

/// Three user clip planes cutting a lit sphere and a lit twisted strip.
fn clip_planes(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.8, 0.7, 0.2, 1.0], 30.0);
    r.call(Call::ClipPlane(0, [1.0, 0.3, 0.0, 1.0]))
        .call(Call::ClipPlane(1, [-0.2, 1.0, 0.1, 1.5]))
        .call(Call::ClipPlane(2, [0.0, 0.0, -1.0, -7.0]))
        .enable(Capability::ClipPlane(0))
        .enable(Capability::ClipPlane(1))
        .enable(Capability::ClipPlane(2));
    sphere(r, [0.0, 0.0, -9.0], 3.5, (32, 24), 1.0);
    // A plane defined under another modelview.
    r.call(Call::PushMatrix)
        .call(Call::Rotate(30.0, [0.0, 0.0, 1.0]))
        .call(Call::ClipPlane(3, [0.0, -1.0, 0.0, 2.5]))
        .call(Call::PopMatrix)
        .enable(Capability::ClipPlane(3));
    sphere(r, [3.0, 3.0, -12.0], 2.5, (16, 12), 1.0);
}

/// A lit sphere and floor under EXP fog.
fn lit_fog(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    material(r, [0.8, 0.3, 0.2, 1.0], 32.0);
    r.enable(Capability::Fog)
        .fog(FogParam::Mode(FogMode::Exp))
        .fog(FogParam::Density(0.09))
        .fog(FogParam::Color([0.6, 0.65, 0.75, 1.0]));
    sphere(r, [-1.5, 0.5, -6.0], 1.8, (24, 16), 1.0);
    sphere(r, [2.5, 1.5, -16.0], 3.0, (24, 16), 1.0);
}

/// Shininess 0 (Mesa's `N·L` quirk for attenuated lights too) and 128.
fn shininess(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.3, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    light(r, 1, [-3.0, 1.0, -5.0, 1.0], [0.6, 0.6, 0.6, 1.0]);
    r.light(1, LightParam::LinearAttenuation(0.2));
    for (k, s) in [0.0, 128.0].into_iter().enumerate() {
        material(r, [0.5, 0.4, 0.8, 1.0], s);
        sphere(r, [-2.2 + 4.4 * k as f32, 0.0, -8.0], 2.0, (24, 16), 1.0);
    }
}

/// A spotlight of exponent 128 (and one of cutoff 90) on a tessellated plane.
fn spot_exponent(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [-2.0, 0.0, -4.0, 1.0], [1.0, 1.0, 1.0, 1.0]);
    r.light(0, LightParam::SpotDirection([0.0, 0.0, -1.0]))
        .light(0, LightParam::SpotExponent(128.0))
        .light(0, LightParam::SpotCutoff(60.0));
    light(r, 1, [2.5, 0.0, -4.0, 1.0], [0.6, 0.8, 1.0, 1.0]);
    r.light(1, LightParam::SpotDirection([0.0, 0.3, -1.0]))
        .light(1, LightParam::SpotExponent(2.0))
        .light(1, LightParam::SpotCutoff(90.0));
    material(r, [0.9, 0.9, 0.9, 1.0], 10.0);
    grid(r, 24, (-6.0, 0.5), -9.0);
}

/// Normals of length 1e-20 and 1e20 on spheres, without `GL_NORMALIZE`
/// (top row) and with it (bottom row), and `GL_RESCALE_NORMAL` under a
/// uniform scale.
fn normal_lengths(r: &mut Rec, _s: Size) {
    lit_view(r);
    light(r, 0, [0.4, 0.6, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]);
    light(r, 1, [0.0, 0.0, -4.0, 1.0], [0.3, 0.3, 0.6, 1.0]);
    material(r, [0.7, 0.6, 0.4, 1.0], 16.0);
    for (row, normalize) in [(2.4, false), (-2.4, true)] {
        if normalize {
            r.enable(Capability::Normalize);
        }
        sphere(r, [-3.0, row, -10.0], 1.8, (16, 12), 1e-20);
        sphere(r, [0.0, row, -10.0], 1.8, (16, 12), 1e20);
        sphere(r, [3.0, row, -10.0], 1.8, (16, 12), 1.0);
    }
    r.disable(Capability::Normalize)
        .enable(Capability::RescaleNormal)
        .call(Call::PushMatrix)
        .call(Call::Scale([0.5, 0.5, 0.5]));
    sphere(r, [0.0, 0.0, -20.0], 1.5, (16, 12), 1.0);
    r.call(Call::PopMatrix).disable(Capability::RescaleNormal);
}
