//! `softgl render MODEL.obj -o out.png [--size WxH]`: loads a Wavefront OBJ
//! with its MTL materials (tobj) and their diffuse textures (image), frames
//! the model's bounding box with a perspective camera, lights it with a key
//! and a fill light, and renders it through softgl's GL API.
//!
//! Every failure is a [`RenderError`] naming the file: a missing or
//! malformed OBJ, MTL or texture never panics.

use glam::{Mat4, Vec3};
use indicatif::{ProgressBar, ProgressStyle};
use softgl::{
    Capability, ClearMask, Context, EnvMode, Face, Filter, FramebufferDesc, InternalFormat, LightModelParam,
    LightParam, MaterialParam, MatrixMode, MipFilter, PixelData, PixelFormat, PixelStore, PixelType, PrimitiveMode,
    TexEnvParam, TexImageTarget, TexParam, TextureTarget,
};
use std::cell::RefCell;
use std::path::{Path, PathBuf};

/// Why a model could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error("cannot read {}: {source}", path.display())]
    Read { path: PathBuf, source: std::io::Error },
    #[error("{} is not a valid OBJ file: {source}", path.display())]
    Obj { path: PathBuf, source: tobj::LoadError },
    #[error("cannot load the material library {}: {why}", path.display())]
    Mtl { path: PathBuf, why: String },
    #[error("cannot load the texture {}: {source}", path.display())]
    Texture { path: PathBuf, source: image::ImageError },
    #[error("{} has no triangles to draw", path.display())]
    Empty { path: PathBuf },
    #[error("softgl: {0}")]
    Gl(#[from] softgl::GlError),
}

/// The background colour (a dark blue-grey), as 8-bit RGBA.
pub const BACKGROUND: [u8; 4] = [38, 43, 51, 255];

/// One mesh ready to draw: flat arrays of positions, normals and (when the
/// OBJ has them) texture coordinates, one entry per index (unindexed).
struct Mesh {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    texcoords: Option<Vec<[f32; 2]>>,
    material: Option<usize>,
}

/// A material as the fixed-function pipeline takes it.
struct Material {
    ambient: [f32; 4],
    diffuse: [f32; 4],
    specular: [f32; 4],
    shininess: f32,
    texture: Option<image::RgbaImage>,
}

/// A loaded model.
pub struct Model {
    meshes: Vec<Mesh>,
    materials: Vec<Material>,
    /// Axis-aligned bounds of every position.
    min: Vec3,
    max: Vec3,
}

impl Model {
    /// Triangles over all meshes.
    pub fn triangles(&self) -> usize {
        self.meshes.iter().map(|m| m.positions.len() / 3).sum()
    }

    /// Meshes that carry a diffuse texture.
    pub fn textured_meshes(&self) -> usize {
        self.meshes
            .iter()
            .filter(|m| m.texcoords.is_some() && m.material.is_some_and(|i| self.materials[i].texture.is_some()))
            .count()
    }
}

/// A progress bar on stderr (hidden when stderr is not a terminal).
fn progress(steps: u64) -> ProgressBar {
    let bar = ProgressBar::new(steps);
    if let Ok(style) = ProgressStyle::with_template("{spinner} loading [{bar:30}] {pos}/{len} {wide_msg}") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

/// Loads `path` with its materials and textures, showing progress.
pub fn load(path: &Path) -> Result<Model, RenderError> {
    let bytes = std::fs::read(path).map_err(|source| RenderError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
    let bar = progress(2);
    bar.set_message(format!("parsing {}", path.display()));
    let mtl_failure = RefCell::new(None);
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, materials) = tobj::load_obj_buf(&mut bytes.as_slice(), &options, |mtl: &Path| {
        let full = dir.join(mtl);
        let result = std::fs::File::open(&full)
            .map_err(|e| e.to_string())
            .and_then(|f| tobj::load_mtl_buf(&mut std::io::BufReader::new(f)).map_err(|e| e.to_string()));
        if let Err(why) = &result {
            *mtl_failure.borrow_mut() = Some(RenderError::Mtl {
                path: full,
                why: why.clone(),
            });
        }
        result.map_err(|_| tobj::LoadError::OpenFileFailed)
    })
    .map_err(|source| RenderError::Obj {
        path: path.to_path_buf(),
        source,
    })?;
    if let Some(e) = mtl_failure.into_inner() {
        return Err(e);
    }
    let materials = materials.map_err(|e| RenderError::Mtl {
        path: path.to_path_buf(),
        why: e.to_string(),
    })?;
    bar.inc(1);
    let textures = materials.iter().filter(|m| m.diffuse_texture.is_some()).count() as u64;
    bar.set_length(2 + textures);
    let mut loaded = Vec::with_capacity(materials.len());
    for m in &materials {
        let texture = match &m.diffuse_texture {
            None => None,
            Some(name) => {
                let tex_path = dir.join(name.replace('\\', "/"));
                bar.set_message(format!("texture {}", tex_path.display()));
                let img = image::open(&tex_path).map_err(|source| RenderError::Texture { path: tex_path, source })?;
                bar.inc(1);
                Some(img.to_rgba8())
            }
        };
        let rgb = |c: Option<[f32; 3]>, d: f32| {
            let c = c.unwrap_or([d; 3]);
            [c[0], c[1], c[2], m.dissolve.unwrap_or(1.0)]
        };
        loaded.push(Material {
            ambient: rgb(m.ambient, 0.2),
            diffuse: rgb(m.diffuse, 0.8),
            specular: rgb(m.specular, 0.0),
            shininess: m.shininess.unwrap_or(0.0).clamp(0.0, 128.0),
            texture,
        });
    }
    let meshes: Vec<Mesh> = models
        .iter()
        .map(|m| mesh(&m.mesh))
        .filter(|m| !m.positions.is_empty())
        .collect();
    bar.inc(1);
    bar.finish_and_clear();
    let mut min = Vec3::splat(f32::INFINITY);
    let mut max = Vec3::splat(f32::NEG_INFINITY);
    for p in meshes.iter().flat_map(|m| &m.positions) {
        let p = Vec3::from_array(*p);
        if p.is_finite() {
            min = min.min(p);
            max = max.max(p);
        }
    }
    if meshes.is_empty() || !min.is_finite() {
        return Err(RenderError::Empty {
            path: path.to_path_buf(),
        });
    }
    Ok(Model {
        meshes,
        materials: loaded,
        min,
        max,
    })
}

/// A tobj mesh unindexed into triangles; normals from the file, or smooth
/// normals averaged from the faces around each vertex.
fn mesh(m: &tobj::Mesh) -> Mesh {
    let at3 = |v: &[f32], i: u32| {
        let i = i as usize * 3;
        v.get(i..i + 3).map_or([0.0; 3], |s| [s[0], s[1], s[2]])
    };
    let tris = m.indices.len() / 3 * 3;
    let indices = &m.indices[..tris];
    let mut smooth = vec![Vec3::ZERO; m.positions.len() / 3];
    if m.normals.is_empty() {
        for t in indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| Vec3::from_array(at3(&m.positions, i)));
            let n = (b - a).cross(c - a);
            for &i in t {
                if let Some(s) = smooth.get_mut(i as usize) {
                    *s += n;
                }
            }
        }
    }
    let normal = |i: u32| {
        if m.normals.is_empty() {
            smooth
                .get(i as usize)
                .map_or([0.0, 0.0, 1.0], |n| n.normalize_or_zero().to_array())
        } else {
            at3(&m.normals, i)
        }
    };
    let texcoords = (!m.texcoords.is_empty()).then(|| {
        indices
            .iter()
            .map(|&i| {
                let i = i as usize * 2;
                m.texcoords.get(i..i + 2).map_or([0.0; 2], |s| [s[0], s[1]])
            })
            .collect()
    });
    Mesh {
        positions: indices.iter().map(|&i| at3(&m.positions, i)).collect(),
        normals: indices.iter().map(|&i| normal(i)).collect(),
        texcoords,
        material: m.material_id,
    }
}

/// The camera: looking at the bounding box's centre from the front, above
/// and to the right, far enough that its bounding sphere fits the view.
fn camera(model: &Model, aspect: f32) -> (Mat4, [f64; 6]) {
    let center = (model.min + model.max) * 0.5;
    let radius = ((model.max - model.min).length() * 0.5).max(1e-6);
    let fovy = 35f32.to_radians();
    let half = (fovy * 0.5).tan();
    // The sphere fits the narrower of the two half-angles.
    let fit = half * aspect.min(1.0);
    let distance = radius / fit.atan().sin() * 1.05;
    let eye = center + Vec3::new(0.35, 0.3, 1.0).normalize() * distance;
    let view = Mat4::look_at_rh(eye, center, Vec3::Y);
    let near = (distance - radius * 1.1).max(distance * 1e-3);
    let far = distance + radius * 1.1;
    let (h, w) = (near * half, near * half * aspect);
    (
        view,
        [-w as f64, w as f64, -h as f64, h as f64, near as f64, far as f64],
    )
}

/// `GL_MAX_TEXTURE_SIZE`: larger images are scaled down to fit.
const MAX_TEXTURE: u32 = 4096;

/// Uploads `img` as a new 2D texture with its mipmaps (trilinear, REPEAT)
/// and returns its name. Rows are flipped: an image's first row is its top,
/// GL's first row (t = 0) the bottom, which is where OBJ's v = 0 is.
fn upload(gl: &mut Context, img: &image::RgbaImage) -> Result<u32, RenderError> {
    let (w, h) = img.dimensions();
    let scale = (MAX_TEXTURE as f32 / w.max(h) as f32).min(1.0);
    let img = if scale < 1.0 {
        let size = |v: u32| ((v as f32 * scale) as u32).clamp(1, MAX_TEXTURE);
        image::imageops::resize(img, size(w), size(h), image::imageops::FilterType::Triangle)
    } else {
        img.clone()
    };
    let flipped = image::imageops::flip_vertical(&img);
    let (w, h) = flipped.dimensions();
    let name = gl.gen_textures(1)?[0];
    let t = TextureTarget::D2;
    gl.bind_texture(t, name)?;
    let pixels = PixelData {
        format: PixelFormat::Rgba,
        ty: PixelType::UnsignedByte,
        store: PixelStore::default(),
        bytes: flipped.as_raw(),
    };
    gl.tex_image(
        TexImageTarget::D2,
        0,
        InternalFormat::Rgba8,
        [w as i32, h as i32, 1],
        0,
        Some(pixels),
    )?;
    gl.generate_mipmap(t)?;
    gl.tex_parameter(t, TexParam::MinFilter(Filter::Linear, MipFilter::Linear))?;
    gl.tex_parameter(t, TexParam::MagFilter(Filter::Linear))?;
    Ok(name)
}

/// Renders `model` at `width` x `height`.
pub fn render(model: &Model, width: u32, height: u32) -> Result<image::RgbaImage, RenderError> {
    let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(width, height))?;
    let bg = BACKGROUND.map(|c| f32::from(c) / 255.0);
    gl.clear_color(bg[0], bg[1], bg[2], bg[3])?;
    gl.clear(ClearMask::ALL)?;
    let (view, [l, r, b, t, n, f]) = camera(model, width as f32 / height as f32);
    gl.matrix_mode(MatrixMode::Projection)?;
    gl.load_identity()?;
    gl.frustum(l, r, b, t, n, f)?;
    gl.matrix_mode(MatrixMode::Modelview)?;
    // The lights are placed in eye space (identity modelview): a key light
    // from the upper left and a dim fill from the right.
    gl.load_identity()?;
    gl.enable(Capability::Lighting)?;
    gl.enable(Capability::Light(0))?;
    gl.enable(Capability::Light(1))?;
    gl.light(0, LightParam::Position([-0.4, 0.6, 1.0, 0.0]))?;
    gl.light(0, LightParam::Diffuse([0.9, 0.9, 0.85, 1.0]))?;
    gl.light(0, LightParam::Specular([0.6, 0.6, 0.6, 1.0]))?;
    gl.light(1, LightParam::Position([1.0, -0.2, 0.4, 0.0]))?;
    gl.light(1, LightParam::Diffuse([0.3, 0.32, 0.4, 1.0]))?;
    gl.light_model(LightModelParam::Ambient([0.25, 0.25, 0.25, 1.0]))?;
    // OBJ files do not agree on winding: light both sides.
    gl.light_model(LightModelParam::TwoSide(true))?;
    gl.load_matrix(&view)?;
    gl.enable(Capability::Normalize)?;
    gl.enable(Capability::DepthTest)?;
    let default = Material {
        ambient: [0.2, 0.2, 0.2, 1.0],
        diffuse: [0.8, 0.8, 0.8, 1.0],
        specular: [0.0, 0.0, 0.0, 1.0],
        shininess: 0.0,
        texture: None,
    };
    let mut names = Vec::with_capacity(model.materials.len());
    for m in &model.materials {
        names.push(m.texture.as_ref().map(|img| upload(&mut gl, img)).transpose()?);
    }
    // The texture modulates the lit colour.
    gl.tex_env(TexEnvParam::Mode(EnvMode::Modulate))?;
    for mesh in &model.meshes {
        let m = mesh.material.and_then(|i| model.materials.get(i)).unwrap_or(&default);
        let texture = mesh.material.and_then(|i| names.get(i).copied().flatten());
        let texcoords = mesh.texcoords.as_deref().filter(|_| texture.is_some());
        match texture {
            Some(name) if texcoords.is_some() => {
                gl.bind_texture(TextureTarget::D2, name)?;
                gl.enable(Capability::Texture(TextureTarget::D2))?;
            }
            _ => gl.disable(Capability::Texture(TextureTarget::D2))?,
        }
        gl.material(Face::FrontAndBack, MaterialParam::Ambient(m.ambient))?;
        gl.material(Face::FrontAndBack, MaterialParam::Diffuse(m.diffuse))?;
        gl.material(Face::FrontAndBack, MaterialParam::Specular(m.specular))?;
        gl.material(Face::FrontAndBack, MaterialParam::Shininess(m.shininess))?;
        gl.begin(PrimitiveMode::Triangles)?;
        for (i, (p, n)) in mesh.positions.iter().zip(&mesh.normals).enumerate() {
            if let Some(st) = texcoords.and_then(|t| t.get(i)) {
                gl.tex_coord([st[0], st[1], 0.0, 1.0]);
            }
            gl.normal3(n[0], n[1], n[2]);
            gl.vertex3(p[0], p[1], p[2]);
        }
        gl.end()?;
    }
    Ok(gl.framebuffer().to_rgba_image())
}
