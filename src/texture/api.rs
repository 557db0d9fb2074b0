//! The texture calls of [`Context`]: objects and bindings, image
//! specification and readback, parameters. Checks and their order follow
//! Mesa 22.3.6 (`main/teximage.c`, `main/texobj.c`, `main/texparam.c`,
//! `main/texgetimage.c`).

use super::format::{InternalFormat, PixelFormat, PixelType};
use super::jit::{BaseFormat, TexTarget, MAX_UNITS};
use super::object::TexImage;
use super::unpack::{self, ClientLayout, Raw, Route};
use super::{max_levels, PixelData, PixelStore, TexImageTarget, TexLevelParamName, TexParam, TexParamName};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::framebuffer::Framebuffer;
use crate::gl_enum::GlEnum;

/// `GL_MAX_TEXTURE_SIZE` (and the cube map size); 3D textures: [`MAX_3D_TEXTURE_SIZE`].
pub const MAX_TEXTURE_SIZE: u32 = 1 << (super::jit::MAX_LEVELS - 1);
/// `GL_MAX_3D_TEXTURE_SIZE`.
pub const MAX_3D_TEXTURE_SIZE: u32 = 1 << (super::jit::MAX_3D_LEVELS - 1);
/// `GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB`: softgl's 2D limit (llvmpipe reports
/// 16384, Mesa's `MaxTextureRectSize` = min(its 2D size, 16384)).
pub const MAX_RECTANGLE_TEXTURE_SIZE: u32 = MAX_TEXTURE_SIZE;

fn check(ok: bool, e: GlError) -> GlResult {
    if ok {
        Ok(())
    } else {
        Err(e)
    }
}

/// `InvalidOperation` unless `format` can carry texels of `internal` and
/// takes `ty` (Mesa's `_mesa_error_check_format_and_type` and
/// `texture_formats_agree`). The C ABI calls it for uploads without data too.
pub fn check_format_type(internal: InternalFormat, format: PixelFormat, ty: PixelType) -> GlResult {
    check(format.type_enum_ok(ty), GlError::InvalidEnum)?;
    check(format.accepts(ty), GlError::InvalidOperation)?;
    check(
        (internal.base() == BaseFormat::Depth) == format.is_depth(),
        GlError::InvalidOperation,
    )
}

/// Whether `size` (border included) is legal for `level` of `target`
/// (`_mesa_legal_texture_dimensions`; every size, not only powers of two).
fn legal_size(target: TexTarget, level: usize, size: [i32; 3], border: i32) -> bool {
    let max = match target {
        TexTarget::D3 => MAX_3D_TEXTURE_SIZE,
        _ => MAX_TEXTURE_SIZE,
    } as i32
        >> level;
    let side = |s: i32| s >= 2 * border && s <= 2 * border + max;
    match target {
        TexTarget::D1 => side(size[0]) && size[1] == 1 && size[2] == 1,
        TexTarget::D2 => side(size[0]) && side(size[1]) && size[2] == 1,
        TexTarget::Cube => side(size[0]) && size[0] == size[1] && size[2] == 1,
        // Mesa's `_mesa_legal_texture_dimensions`: level 0, any size up to the maximum.
        TexTarget::Rect => {
            let ok = |s: i32| (0..=MAX_RECTANGLE_TEXTURE_SIZE as i32).contains(&s);
            level == 0 && ok(size[0]) && ok(size[1]) && size[2] == 1
        }
        TexTarget::D3 => side(size[0]) && side(size[1]) && side(size[2]),
    }
}

/// The size with the border stripped, and the unpack state skipping it
/// (Mesa's `strip_texture_border`: llvmpipe keeps no borders).
fn strip_border(dims: u32, size: [i32; 3], store: &PixelStore) -> ([i32; 3], PixelStore) {
    let mut s = *store;
    let mut size = size;
    if s.row_length == 0 {
        s.row_length = size[0];
    }
    if s.image_height == 0 {
        s.image_height = size[1];
    }
    s.skip_pixels += 1;
    size[0] -= 2;
    if dims >= 2 && size[1] >= 3 {
        s.skip_rows += 1;
        size[1] -= 2;
    }
    if dims == 3 && size[2] >= 3 {
        s.skip_images += 1;
        size[2] -= 2;
    }
    (size, s)
}

/// The layout of `pixels` for a `size` image, checking that its bytes hold it.
fn client_layout(pixels: &PixelData<'_>, store: &PixelStore, dims: u32, size: [usize; 3]) -> GlResult<ClientLayout> {
    let layout = ClientLayout::new(pixels.format, pixels.ty, store, dims, size).ok_or(GlError::InvalidOperation)?;
    check(pixels.bytes.len() >= layout.len, GlError::InvalidOperation)?;
    Ok(layout)
}

/// Whether `border` is allowed: 0 or 1, and 0 only for rectangle textures
/// (Mesa's `texture_error_check` and `copytexture_error_check`).
fn legal_border(target: TexTarget, border: i32) -> bool {
    match target {
        TexTarget::Rect => border == 0,
        TexTarget::D1 | TexTarget::D2 | TexTarget::D3 | TexTarget::Cube => matches!(border, 0 | 1),
    }
}

/// A rectangle texture's `glTexParameter` limits (Mesa `main/texparam.c`):
/// no REPEAT or MIRRORED_REPEAT (`validate_texture_wrap_mode`) and no
/// mipmap minification filter (`InvalidEnum`), BASE_LEVEL 0 only
/// (`InvalidOperation`), MAX_LEVEL 0 only (`InvalidValue`); setting a value
/// a parameter already has is never an error there.
fn check_rect_param(params: &super::SamplerState, p: &TexParam) -> GlResult {
    use super::jit::{MipFilter, Wrap};
    let wrap_ok = |w: &Wrap| !matches!(w, Wrap::Repeat | Wrap::MirroredRepeat);
    match p {
        TexParam::WrapS(w) | TexParam::WrapT(w) | TexParam::WrapR(w) => check(wrap_ok(w), GlError::InvalidEnum),
        TexParam::MinFilter(_, m) => check(*m == MipFilter::None, GlError::InvalidEnum),
        TexParam::BaseLevel(v) => check(*v == 0, GlError::InvalidOperation),
        TexParam::MaxLevel(v) => check(*v == params.max_level || *v == 0, GlError::InvalidValue),
        _ => Ok(()),
    }
}

fn level_index(target: TexTarget, level: i32) -> GlResult<usize> {
    usize::try_from(level)
        .ok()
        .filter(|&l| l < max_levels(target))
        .ok_or(GlError::InvalidValue)
}

/// The framebuffer's pixels of a rectangle as client pixels (RGBA ubyte, or
/// the stored depth), the way Mesa's copies read them; pixels outside the
/// framebuffer are `None`.
fn read_source(fb: &Framebuffer, depth: bool, x: i32, y: i32) -> Option<[Raw; 4]> {
    let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
    if depth {
        let format = fb.depth_format()?;
        let z = fb.depth_at(x, y)?;
        let d = match format {
            softgl_jit::DepthFormat::D32F => Raw::F(f32::from_bits(z)),
            f => Raw::U(z, f.bits()),
        };
        Some([d, Raw::ZERO, Raw::ZERO, Raw::ONE])
    } else {
        Some(fb.pixel(x, y)?.map(|c| Raw::U(u32::from(c), 8)))
    }
}

/// Copies the framebuffer rectangle at `xy` of `fb` into `img` at `offset`
/// (slice `offset[2]` for 3D); pixels outside the framebuffer are left as they are.
fn copy_into_slice(
    fb: &Framebuffer,
    img: &mut TexImage,
    offset: [usize; 3],
    xy: [i32; 2],
    size: [i32; 2],
    depth: bool,
    transfer: Option<&crate::pixel_transfer::PixelState>,
) {
    let format = if depth {
        PixelFormat::DepthComponent
    } else {
        PixelFormat::Rgba
    };
    for j in 0..size[1].max(0) {
        for i in 0..size[0].max(0) {
            let (x, y) = (i64::from(xy[0]) + i64::from(i), i64::from(xy[1]) + i64::from(j));
            let (Ok(x), Ok(y)) = (i32::try_from(x), i32::try_from(y)) else {
                continue;
            };
            if let Some(rgba) = read_source(fb, depth, x, y) {
                // Mesa's copy through a float image and the texture store
                // (`fallback_copy_texsubimage`, `st_cb_texture.c`).
                let rgba = transfer.map_or(rgba, |t| unpack::transfer(t, format, rgba));
                let at = (offset[0] + i as usize, offset[1] + j as usize, offset[2]);
                unpack::store_texel(img, at, rgba, Route::Direct);
            }
        }
    }
}

impl Context {
    /// Records `r`'s error GL-style and passes `r` on; every texture call
    /// starts by refusing to run between `begin` and `end`.
    fn tex_call<T>(&mut self, f: impl FnOnce(&mut Context) -> GlResult<T>) -> GlResult<T> {
        let r = if self.inside_begin() {
            Err(GlError::InvalidOperation)
        } else {
            self.outside().and_then(|()| f(self))
        };
        if let Err(e) = r {
            self.record_error(e);
        }
        r
    }

    /// The texture objects and bindings.
    pub fn textures(&self) -> &super::TextureStore {
        &self.textures
    }

    /// `glActiveTexture(GL_TEXTURE0 + unit)`; `InvalidEnum` past the last unit.
    pub fn active_texture(&mut self, unit: u32) -> GlResult {
        self.tex_call(|gl| {
            check((unit as usize) < MAX_UNITS, GlError::InvalidEnum)?;
            gl.textures.get_mut().set_active_unit(unit as usize);
            Ok(())
        })
    }

    /// The active texture unit.
    pub fn active_texture_unit(&self) -> usize {
        self.textures.active_unit()
    }

    /// `glGenTextures`: `n` names never used before.
    pub fn gen_textures(&mut self, n: i32) -> GlResult<Vec<u32>> {
        self.tex_call(|gl| {
            let n = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
            gl.textures.get_mut().gen(n).ok_or(GlError::OutOfMemory)
        })
    }

    /// `glBindTexture` on the active unit: name 0 is the target's default
    /// texture; a new name creates an object; an object of another target is
    /// `InvalidOperation`.
    pub fn bind_texture(&mut self, target: TexTarget, name: u32) -> GlResult {
        self.tex_call(|gl| check(gl.textures.get_mut().bind(target, name), GlError::InvalidOperation))
    }

    /// `glDeleteTextures`: bindings of deleted objects revert to 0; unknown names are ignored.
    pub fn delete_textures(&mut self, names: &[u32]) {
        for &name in names {
            self.forget_texture(name);
        }
        let _ = self.tex_call(|gl| {
            gl.textures.get_mut().delete(names);
            Ok(())
        });
    }

    /// `glIsTexture`: a name with an object (generated names count once bound).
    pub fn is_texture(&self, name: u32) -> bool {
        !self.inside_begin() && self.textures.is_texture(name)
    }

    /// The name bound to `target` on `unit` (`GL_TEXTURE_BINDING_*`).
    pub fn texture_binding(&self, unit: usize, target: TexTarget) -> u32 {
        self.textures.binding(unit, target)
    }

    /// `glPrioritizeTextures`: priorities clamped to [0, 1]; names without
    /// objects (and 0) are skipped.
    pub fn prioritize_textures(&mut self, names: &[u32], priorities: &[f32]) {
        let _ = self.tex_call(|gl| {
            for (&name, &p) in names.iter().zip(priorities) {
                if let Some(obj) = gl.textures.get_mut().object_mut(name) {
                    obj.params.priority = p.clamp(0.0, 1.0);
                }
            }
            Ok(())
        });
    }

    /// `glAreTexturesResident`: every texture is resident; a name without an
    /// object (or 0) is `InvalidValue`.
    pub fn are_textures_resident(&mut self, names: &[u32]) -> GlResult<Vec<bool>> {
        self.tex_call(|gl| {
            check(names.iter().all(|&n| gl.textures.exists(n)), GlError::InvalidValue)?;
            Ok(vec![true; names.len()])
        })
    }

    /// Rasterizes the pending draws first when they hold texels of the
    /// texture bound to `target` on the active unit, as llvmpipe flushes a
    /// scene before a resource it reads is written: the write then needs no
    /// copy of the texels, and the scene never holds more than one old copy
    /// of a texture (a client streaming uploads between draws would
    /// otherwise pile them up).
    fn before_texture_write(&mut self, target: TexTarget) {
        self.sync_texture(self.textures.binding(self.textures.active_unit(), target));
        let obj = self.textures.bound(self.textures.active_unit(), target);
        if obj
            .images
            .iter()
            .flatten()
            .any(|i| std::sync::Arc::strong_count(&i.texels) > 1)
        {
            self.finish_scene();
        }
    }

    /// `glTexImage1D/2D/3D` (sizes `[w, 1, 1]`, `[w, h, 1]`, `[w, h, d]`).
    /// `pixels: None` allocates the image without data (texels read as 0).
    pub fn tex_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        internal: InternalFormat,
        size: [i32; 3],
        border: i32,
        pixels: Option<PixelData<'_>>,
    ) -> GlResult {
        self.before_texture_write(target.texture_target());
        self.tex_call(|gl| {
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            check(legal_border(tt, border), GlError::InvalidValue)?;
            check(size.iter().all(|&s| s >= 0), GlError::InvalidValue)?;
            if let Some(p) = &pixels {
                check_format_type(internal, p.format, p.ty)?;
            }
            check(
                !(internal.base() == BaseFormat::Depth && tt == TexTarget::D3),
                GlError::InvalidOperation,
            )?;
            let legal = legal_size(tt, level, size, border);
            if let TexImageTarget::Proxy(t) = target {
                // Proxies: a size the texture cannot have clears the image instead
                // of an error; sizes are kept with their border.
                let img = legal.then(|| TexImage {
                    width: size[0] as u32,
                    height: size[1] as u32,
                    depth: size[2] as u32,
                    border: border as u32,
                    internal,
                    texels: Default::default(),
                    units: None,
                });
                if let Some(slot) = gl.textures.get_mut().proxy_mut(t).image_mut(level, 0) {
                    *slot = img;
                }
                return Ok(());
            }
            check(legal, GlError::InvalidValue)?;
            let dims = target.dims();
            let store = pixels.as_ref().map_or(PixelStore::DEFAULT, |p| p.store);
            let (size, store) = if border == 1 {
                strip_border(dims, size, &store)
            } else {
                (size, store)
            };
            let usize3 = size.map(|s| s as usize);
            let mut img = TexImage::new(internal, size.map(|s| s as u32));
            if let Some(p) = pixels.filter(|_| !usize3.contains(&0)) {
                let layout = client_layout(&p, &store, dims, usize3)?;
                let transfer = Some(&gl.pixel).filter(|t| !t.is_identity());
                unpack::upload(&mut img, [0; 3], usize3, &PixelData { store, ..p }, &layout, transfer);
            }
            let obj = gl.textures.get_mut().current_mut(tt);
            if let Some(slot) = obj.image_mut(level, target.face()) {
                *slot = Some(img);
            }
            gl.check_gen_mipmap(target, level)
        })
    }

    /// Mesa's `check_gen_mipmap`: after the base level of a face changes,
    /// with `GL_GENERATE_MIPMAP` on, that face's chain below it is rebuilt.
    fn check_gen_mipmap(&mut self, target: TexImageTarget, level: usize) -> GlResult {
        let obj = self.textures.get_mut().current_mut(target.texture_target());
        if obj.params.generate_mipmap && level as i32 == obj.params.base_level {
            let face = target.face();
            super::mipmap::generate(obj, face..face + 1);
        }
        Ok(())
    }

    /// The image of the bound texture a sub-image call writes (`InvalidOperation` when missing).
    fn existing_image(&self, target: TexImageTarget, level: usize) -> GlResult<&TexImage> {
        let obj = self
            .textures
            .bound(self.textures.active_unit(), target.texture_target());
        obj.image(level, target.face()).ok_or(GlError::InvalidOperation)
    }

    /// Checks a sub-image region against the image (`error_check_subtexture_dimensions`);
    /// dimensions the target lacks must be offset 0, size 1.
    fn check_region(img: &TexImage, dims: u32, offset: [i32; 3], size: [i32; 3]) -> GlResult {
        let img_size = img.size();
        for d in 0..3 {
            let (o, s) = (i64::from(offset[d]), i64::from(size[d]));
            if d as u32 >= dims {
                check(o == 0 && s == 1, GlError::InvalidValue)?;
                continue;
            }
            check(o >= 0 && o + s <= i64::from(img_size[d]), GlError::InvalidValue)?;
        }
        Ok(())
    }

    /// `glTexSubImage1D/2D/3D`.
    pub fn tex_sub_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        pixels: PixelData<'_>,
    ) -> GlResult {
        self.before_texture_write(target.texture_target());
        self.tex_call(|gl| {
            check(!matches!(target, TexImageTarget::Proxy(_)), GlError::InvalidEnum)?;
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            check(size.iter().all(|&s| s >= 0), GlError::InvalidValue)?;
            let img = gl.existing_image(target, level)?;
            check_format_type(img.internal, pixels.format, pixels.ty)?;
            Context::check_region(img, target.dims(), offset, size)?;
            let usize3 = size.map(|s| s as usize);
            if usize3.contains(&0) {
                return Ok(());
            }
            let layout = client_layout(&pixels, &pixels.store, target.dims(), usize3)?;
            let transfer = Some(&gl.pixel).filter(|t| !t.is_identity());
            let obj = gl.textures.get_mut().current_mut(tt);
            if let Some(Some(img)) = obj.image_mut(level, target.face()) {
                unpack::upload(img, offset.map(|o| o as usize), usize3, &pixels, &layout, transfer);
            }
            gl.check_gen_mipmap(target, level)
        })
    }

    /// `glTexSubImage` with no image (a null pointer, no unpack buffer):
    /// its errors only, as [`Context::tex_sub_image`] finds them, and
    /// nothing written (Mesa checks the region before it looks at the
    /// pointer: `texsubimage_error_check`, `main/teximage.c`).
    pub fn tex_sub_image_errors(
        &mut self,
        target: TexImageTarget,
        level: i32,
        offset: [i32; 3],
        size: [i32; 3],
        (format, ty): (PixelFormat, PixelType),
    ) -> GlResult {
        self.tex_call(|gl| {
            check(!matches!(target, TexImageTarget::Proxy(_)), GlError::InvalidEnum)?;
            let level = level_index(target.texture_target(), level)?;
            check(size.iter().all(|&s| s >= 0), GlError::InvalidValue)?;
            let img = gl.existing_image(target, level)?;
            check_format_type(img.internal, format, ty)?;
            Context::check_region(img, target.dims(), offset, size)
        })
    }

    /// `glCopyTexImage1D/2D`: the image from the framebuffer rectangle at
    /// `xy` (`size` `[w, 1]` for 1D). Colour formats read the colour buffer
    /// (luminance and intensity take red), depth formats the depth buffer.
    pub fn copy_tex_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        internal: InternalFormat,
        xy: [i32; 2],
        size: [i32; 2],
        border: i32,
    ) -> GlResult {
        self.sync_texture(
            self.textures
                .binding(self.textures.active_unit(), target.texture_target()),
        );
        self.finish_scene();
        self.tex_call(|gl| {
            check(
                matches!(
                    target,
                    TexImageTarget::D1 | TexImageTarget::D2 | TexImageTarget::CubeFace(_) | TexImageTarget::Rect
                ),
                GlError::InvalidEnum,
            )?;
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            check(legal_border(tt, border), GlError::InvalidValue)?;
            check(
                !matches!(
                    internal,
                    InternalFormat::One | InternalFormat::Two | InternalFormat::Three | InternalFormat::Four
                ),
                GlError::InvalidEnum,
            )?;
            let depth = internal.base() == BaseFormat::Depth;
            let view = gl.take_read_unflushed(!depth)?;
            check(
                !depth || gl.read_ref(&view).depth_format().is_some(),
                GlError::InvalidOperation,
            )?;
            check(size.iter().all(|&s| s >= 0), GlError::InvalidValue)?;
            let full = [size[0], if target.dims() == 1 { 1 } else { size[1] }, 1];
            check(legal_size(tt, level, full, border), GlError::InvalidValue)?;
            let (stripped, xy) = if border == 1 {
                let dy = i32::from(target.dims() == 2 && full[1] >= 3);
                ([full[0] - 2, full[1] - 2 * dy, 1], [xy[0] + 1, xy[1] + dy])
            } else {
                (full, xy)
            };
            let mut img = TexImage::new(internal, stripped.map(|s| s as u32));
            let region = [stripped[0], stripped[1]];
            let transfer = Some(&gl.pixel).filter(|t| !t.is_identity());
            copy_into_slice(gl.read_ref(&view), &mut img, [0, 0, 0], xy, region, depth, transfer);
            if let Some(slot) = gl.textures.get_mut().current_mut(tt).image_mut(level, target.face()) {
                *slot = Some(img);
            }
            gl.check_gen_mipmap(target, level)
        })
    }

    /// `glCopyTexSubImage1D/2D/3D`: `offset` `[x, 0, 0]` for 1D, `[x, y, 0]`
    /// for 2D and cube faces, `[x, y, z]` for 3D (one slice).
    pub fn copy_tex_sub_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        offset: [i32; 3],
        xy: [i32; 2],
        size: [i32; 2],
    ) -> GlResult {
        self.sync_texture(
            self.textures
                .binding(self.textures.active_unit(), target.texture_target()),
        );
        self.finish_scene();
        self.tex_call(|gl| {
            check(!matches!(target, TexImageTarget::Proxy(_)), GlError::InvalidEnum)?;
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            let img = gl.existing_image(target, level)?;
            check(size.iter().all(|&s| s >= 0), GlError::InvalidValue)?;
            let dims = target.dims();
            let region = [size[0], if dims == 1 { 1 } else { size[1] }, 1];
            let off = [
                offset[0],
                if dims == 1 { 0 } else { offset[1] },
                if dims == 3 { offset[2] } else { 0 },
            ];
            for d in 0..dims as usize {
                let (o, s) = (i64::from(off[d]), i64::from(region[d]));
                check(o >= 0 && o + s <= i64::from(img.size()[d]), GlError::InvalidValue)?;
            }
            let depth = img.internal.base() == BaseFormat::Depth;
            let mut img = img.clone();
            let view = gl.take_read_unflushed(!depth)?;
            let fb = gl.read_ref(&view);
            check(!depth || fb.depth_format().is_some(), GlError::InvalidOperation)?;
            let at = off.map(|o| o as usize);
            let transfer = Some(&gl.pixel).filter(|t| !t.is_identity());
            copy_into_slice(fb, &mut img, at, xy, [region[0], region[1]], depth, transfer);
            if let Some(slot) = gl.textures.get_mut().current_mut(tt).image_mut(level, target.face()) {
                *slot = Some(img);
            }
            gl.check_gen_mipmap(target, level)
        })
    }

    /// `glGetTexImage` of the bound texture into `out`, laid out by `pack`.
    /// A level without an image writes nothing.
    pub fn get_tex_image(
        &mut self,
        target: TexImageTarget,
        level: i32,
        format: PixelFormat,
        ty: PixelType,
        pack: &PixelStore,
        out: &mut [u8],
    ) -> GlResult {
        self.sync_texture(
            self.textures
                .binding(self.textures.active_unit(), target.texture_target()),
        );
        self.tex_call(|gl| {
            check(!matches!(target, TexImageTarget::Proxy(_)), GlError::InvalidEnum)?;
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            check(format.type_enum_ok(ty), GlError::InvalidEnum)?;
            check(format.accepts(ty), GlError::InvalidOperation)?;
            let obj = gl.textures.bound(gl.textures.active_unit(), tt);
            let Some(img) = obj.image(level, target.face()) else {
                return Ok(());
            };
            check(
                (img.internal.base() == BaseFormat::Depth) == format.is_depth(),
                GlError::InvalidOperation,
            )?;
            // Mesa `getteximage_error_check`: depth-stencil data only from a depth-stencil image.
            check(
                format != PixelFormat::DepthStencil || img.internal.stencil_bits() > 0,
                GlError::InvalidOperation,
            )?;
            let size = img.size().map(|s| s as usize);
            let layout = ClientLayout::new(format, ty, pack, target.dims(), size).ok_or(GlError::InvalidOperation)?;
            check(out.len() >= layout.len, GlError::InvalidOperation)?;
            unpack::download(img, format, ty, pack.swap_bytes, &layout, out);
            Ok(())
        })
    }

    /// `glTexParameter` on the active unit's `target`.
    pub fn tex_parameter(&mut self, target: TexTarget, p: TexParam) -> GlResult {
        self.set_tex_parameter(target, p, true)
    }

    /// A parameter value `glPushAttrib(GL_TEXTURE_BIT)` saved, put back as
    /// Mesa's `glPopAttrib` copies it: without the rectangle target's limits
    /// (a rectangle texture's saved MAX_LEVEL of 1000 is restored even when 0
    /// was set since, which `glTexParameter` would refuse).
    pub fn restore_tex_parameter(&mut self, target: TexTarget, p: TexParam) -> GlResult {
        self.set_tex_parameter(target, p, false)
    }

    fn set_tex_parameter(&mut self, target: TexTarget, p: TexParam, checked: bool) -> GlResult {
        self.tex_call(|gl| {
            let params = &mut gl.textures.get_mut().current_mut(target).params;
            if checked && target == TexTarget::Rect {
                check_rect_param(params, &p)?;
            }
            match p {
                TexParam::MinFilter(f, m) => (params.min, params.mip) = (f, m),
                TexParam::MagFilter(f) => params.mag = f,
                TexParam::WrapS(w) => params.wrap[0] = w,
                TexParam::WrapT(w) => params.wrap[1] = w,
                TexParam::WrapR(w) => params.wrap[2] = w,
                // Kept unclamped, as Mesa with ARB_texture_float (a float depth
                // texture samples it so); the sampler clamps it for the others,
                // the query below answers it clamped (`main/texparam.c`).
                TexParam::BorderColor(c) => params.border = c,
                TexParam::MinLod(v) => params.min_lod = v,
                TexParam::MaxLod(v) => params.max_lod = v,
                TexParam::BaseLevel(v) => {
                    check(v >= 0, GlError::InvalidValue)?;
                    params.base_level = v;
                }
                TexParam::MaxLevel(v) => {
                    check(v >= 0, GlError::InvalidValue)?;
                    params.max_level = v;
                }
                TexParam::LodBias(v) => params.lod_bias = v,
                TexParam::Priority(v) => params.priority = v.clamp(0.0, 1.0),
                TexParam::GenerateMipmap(on) => params.generate_mipmap = on,
                TexParam::CompareMode(on) => params.compare = on,
                TexParam::CompareFunc(f) => params.compare_func = f,
                TexParam::DepthMode(m) => params.depth_mode = m,
                TexParam::Resident(_) => return Err(GlError::InvalidEnum),
            }
            Ok(())
        })
    }

    /// `glGetTexParameter` of the active unit's `target`.
    pub fn get_tex_parameter(&mut self, target: TexTarget, name: TexParamName) -> GlResult<TexParam> {
        self.tex_call(|gl| {
            let p = gl.textures.bound(gl.textures.active_unit(), target).params;
            Ok(match name {
                TexParamName::MinFilter => TexParam::MinFilter(p.min, p.mip),
                TexParamName::MagFilter => TexParam::MagFilter(p.mag),
                TexParamName::WrapS => TexParam::WrapS(p.wrap[0]),
                TexParamName::WrapT => TexParam::WrapT(p.wrap[1]),
                TexParamName::WrapR => TexParam::WrapR(p.wrap[2]),
                TexParamName::BorderColor => TexParam::BorderColor(p.border.map(|v| v.clamp(0.0, 1.0))),
                TexParamName::MinLod => TexParam::MinLod(p.min_lod),
                TexParamName::MaxLod => TexParam::MaxLod(p.max_lod),
                TexParamName::BaseLevel => TexParam::BaseLevel(p.base_level),
                TexParamName::MaxLevel => TexParam::MaxLevel(p.max_level),
                TexParamName::LodBias => TexParam::LodBias(p.lod_bias),
                TexParamName::Priority => TexParam::Priority(p.priority),
                TexParamName::GenerateMipmap => TexParam::GenerateMipmap(p.generate_mipmap),
                TexParamName::CompareMode => TexParam::CompareMode(p.compare),
                TexParamName::CompareFunc => TexParam::CompareFunc(p.compare_func),
                TexParamName::DepthMode => TexParam::DepthMode(p.depth_mode),
                TexParamName::Resident => TexParam::Resident(true),
            })
        })
    }

    /// `glGetTexLevelParameteriv`. A level without an image reports 0, and
    /// `GL_RGBA` as its internal format (Mesa's dummy image).
    pub fn get_tex_level_parameter(
        &mut self,
        target: TexImageTarget,
        level: i32,
        name: TexLevelParamName,
    ) -> GlResult<i32> {
        self.tex_call(|gl| {
            let tt = target.texture_target();
            let level = level_index(tt, level)?;
            let obj = match target {
                TexImageTarget::Proxy(t) => gl.textures.proxy(t),
                _ => gl.textures.bound(gl.textures.active_unit(), tt),
            };
            let Some(img) = obj.image(level, target.face()) else {
                return Ok(match name {
                    TexLevelParamName::InternalFormat => InternalFormat::Rgba.to_gl() as i32,
                    _ => 0,
                });
            };
            let s = img.internal.storage();
            let color = |c: usize, bases: &[BaseFormat]| if bases.contains(&s.base) { s.bits[c] as i32 } else { 0 };
            use BaseFormat as B;
            Ok(match name {
                TexLevelParamName::Width => img.width as i32,
                TexLevelParamName::Height => img.height as i32,
                TexLevelParamName::Depth => img.depth as i32,
                TexLevelParamName::Border => img.border as i32,
                TexLevelParamName::InternalFormat => img.internal.reported().to_gl() as i32,
                TexLevelParamName::RedSize => color(0, &[B::Rgb, B::Rgba]),
                TexLevelParamName::GreenSize => color(1, &[B::Rgb, B::Rgba]),
                TexLevelParamName::BlueSize => color(2, &[B::Rgb, B::Rgba]),
                TexLevelParamName::AlphaSize => color(3, &[B::Alpha, B::LuminanceAlpha, B::Rgba]),
                TexLevelParamName::LuminanceSize => color(0, &[B::Luminance, B::LuminanceAlpha]),
                TexLevelParamName::IntensitySize => color(0, &[B::Intensity]),
                TexLevelParamName::DepthSize => color(0, &[B::Depth]),
                TexLevelParamName::StencilSize => img.internal.stencil_bits() as i32,
                TexLevelParamName::Compressed => 0,
            })
        })
    }

    /// `glGenerateMipmap` for the active unit's `target` (Mesa `main/genmipmap.c`):
    /// nothing when BASE_LEVEL ≥ MAX_LEVEL; `InvalidOperation` for a cube map
    /// whose base faces differ, or without a base image.
    /// A rectangle texture is `InvalidEnum` (`_mesa_is_valid_generate_texture_mipmap_target`).
    pub fn generate_mipmap(&mut self, target: TexTarget) -> GlResult {
        self.before_texture_write(target);
        self.tex_call(|gl| {
            check(target != TexTarget::Rect, GlError::InvalidEnum)?;
            let obj = gl.textures.get_mut().current_mut(target);
            if obj.params.base_level >= obj.params.max_level {
                return Ok(());
            }
            let base_level = obj.params.base_level as usize;
            if target == TexTarget::Cube {
                let base = obj.image(base_level, 0).ok_or(GlError::InvalidOperation)?;
                let same = (1..6).all(|f| {
                    obj.image(base_level, f)
                        .is_some_and(|i| i.size() == base.size() && i.internal == base.internal)
                });
                check(same && base.width == base.height, GlError::InvalidOperation)?;
            }
            let base = obj.base_image().ok_or(GlError::InvalidOperation)?;
            if base.width == 0 || base.height == 0 {
                return Ok(());
            }
            let faces = obj.faces();
            super::mipmap::generate(obj, 0..faces);
            Ok(())
        })
    }
}
