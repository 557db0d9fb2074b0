//! A compiled specialist and the one place softgl calls into generated code.

use crate::callout::TexView;
use crate::compile::{self, CompileError, SpanCall, SpanFn};
use crate::interp::{check_key, check_planes, owned_mask, row_of, FragmentError};
use crate::key::FragmentKey;
use crate::pixel;
use crate::shade::Planes;
use crate::span::{FragmentSpan, SPAN_MAX};
use crate::target::{DepthTarget, Target};
use crate::texture::TextureSet;
use crate::uniforms::FragmentUniforms;
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{Module, ModuleError};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::OnceLock;

/// Why a specialist could not be made.
#[derive(Debug, thiserror::Error)]
pub enum SpecialistError {
    #[error(transparent)]
    Key(#[from] crate::key::KeyError),
    #[error(transparent)]
    Compile(#[from] CompileError),
    #[error("the compiler panicked: {0}")]
    Panic(String),
}

/// The host ISA ([`compile::host_isa`]), made once per process.
fn isa() -> Result<&'static OwnedTargetIsa, SpecialistError> {
    static ISA: OnceLock<Result<OwnedTargetIsa, String>> = OnceLock::new();
    ISA.get_or_init(|| compile::host_isa().map_err(|e| e.to_string()))
        .as_ref()
        .map_err(|e| SpecialistError::Compile(CompileError::Isa(e.clone())))
}

/// One key's stages compiled to native code, in a module of its own so that
/// dropping the specialist frees its code pages.
pub struct Specialist {
    key: FragmentKey,
    func: SpanFn,
    module: Option<JITModule>,
}

// SAFETY: the module's code and data are immutable after finalization and owned
// by this value alone; its interior `RefCell`s are only touched while compiling,
// before the value exists, and by `free_memory` in `drop` (which takes `&mut self`).
unsafe impl Send for Specialist {}

impl std::fmt::Debug for Specialist {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Specialist")
            .field("key", &self.key)
            .finish_non_exhaustive()
    }
}

impl Specialist {
    /// Compiles `key`. A panic inside Cranelift is caught and returned as an error.
    pub fn compile(key: &FragmentKey) -> Result<Specialist, SpecialistError> {
        key.validate()?;
        let isa = isa()?;
        catch_unwind(AssertUnwindSafe(|| Self::compile_with(key, isa))).unwrap_or_else(|p| {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(SpecialistError::Panic(msg))
        })
    }

    fn compile_with(key: &FragmentKey, isa: &OwnedTargetIsa) -> Result<Specialist, SpecialistError> {
        let mut module = JITModule::new(JITBuilder::with_isa(
            isa.clone(),
            cranelift_module::default_libcall_names(),
        ));
        let built = (|| -> Result<*const u8, Box<ModuleError>> {
            let mut ctx = module.make_context();
            ctx.func.signature = compile::signature(isa);
            compile::build(key, isa, &mut ctx.func);
            let id = module.declare_anonymous_function(&ctx.func.signature)?;
            module.define_function(id, &mut ctx)?;
            module.finalize_definitions()?;
            Ok(module.get_finalized_function(id))
        })();
        match built {
            Ok(code) => {
                // SAFETY: `code` is the finalized function built with `compile::signature`,
                // which is `SpanFn`'s ABI (two pointers, no result, the ISA's default
                // convention), and it lives as long as `module`, which this value owns.
                let func = unsafe { std::mem::transmute::<*const u8, SpanFn>(code) };
                Ok(Specialist {
                    key: *key,
                    func,
                    module: Some(module),
                })
            }
            Err(e) => {
                // SAFETY: nothing from the module was ever called or handed out.
                unsafe { module.free_memory() };
                Err(SpecialistError::Compile(CompileError::Module(e)))
            }
        }
    }

    /// The key this specialist was compiled for.
    pub fn key(&self) -> &FragmentKey {
        &self.key
    }

    /// Runs the stages over `spans` into `target`: the same result as
    /// [`crate::interp::run`] with the same key, bit for bit.
    pub fn run(
        &self,
        uniforms: &FragmentUniforms,
        spans: &[FragmentSpan],
        target: &mut Target<'_>,
    ) -> Result<(), FragmentError> {
        self.run_with_planes(uniforms, &TextureSet::default(), spans, &[], target)
    }

    /// [`Self::run`] for keys with a shading stage: the same result as
    /// [`crate::interp::run_with_planes`], bit for bit.
    pub fn run_with_planes(
        &self,
        uniforms: &FragmentUniforms,
        textures: &TextureSet<'_>,
        spans: &[FragmentSpan],
        planes: &[Planes],
        target: &mut Target<'_>,
    ) -> Result<(), FragmentError> {
        check_key(&self.key, target)?;
        check_planes(&self.key, spans, planes)?;
        let view = match self.key.shade.as_ref().filter(|s| s.textured()) {
            Some(shade) => match TexView::new(&shade.tex, textures) {
                Some(view) => Some(view),
                // A natively sampled unit without a texture it can read.
                None => return crate::interp::run_with_planes(&self.key, uniforms, textures, spans, planes, target),
            },
            None => None,
        };
        let tex = view
            .as_ref()
            .map_or(std::ptr::null(), |v| (v as *const TexView<'_>).cast());
        for span in spans {
            let p = planes
                .get(span.planes as usize)
                .map_or(std::ptr::null(), |p| p as *const Planes);
            self.run_span((uniforms, tex), (span, p), target);
        }
        Ok(())
    }

    fn run_span(
        &self,
        (u, tex): (&FragmentUniforms, *const TexView<'static>),
        (span, planes): (&FragmentSpan, *const Planes),
        t: &mut Target<'_>,
    ) {
        let live = owned_mask(span, t.width(), t.height());
        if live == 0 {
            return;
        }
        let groups = (64 - live.leading_zeros()).div_ceil(4);
        let n = 4 * groups as usize;
        let inside = (t.width() - span.x).min(SPAN_MAX as u32) as usize;
        let mut call = SpanCall {
            span,
            color: std::ptr::null_mut(),
            depth: std::ptr::null_mut(),
            stencil: std::ptr::null_mut(),
            live,
            groups,
            _pad: 0,
            dither: if self.key.dither {
                std::array::from_fn(|i| pixel::dither_bias(span.x + i as u32, span.y))
            } else {
                [0; 4]
            },
            planes,
            row: row_of(span.y, t.height()),
            _pad2: 0,
            tex,
        };
        let bpp = self.key.color_format.bytes_per_pixel();
        let color_at = t.color_offset(span.x, span.y);
        let index = t.index(span.x, span.y);
        let (color, depth, stencil) = t.parts_mut();
        // Whole groups inside the row are run in place; when the last group
        // crosses the right edge, on a copy of the row's end padded to whole groups.
        let len = n.min(inside);
        let Some(color) = color.get_mut(color_at..color_at + len * bpp) else {
            return;
        };
        let mut depth = match depth {
            Some(d) => match depth_row(d, index, len) {
                Some(row) => Some(row),
                None => return,
            },
            None => None,
        };
        let mut stencil = match stencil {
            Some(s) => match s.get_mut(index..index + len) {
                Some(row) => Some(row),
                None => return,
            },
            None => None,
        };
        if n <= inside {
            call.color = color.as_mut_ptr();
            call.depth = depth.as_mut().map_or(std::ptr::null_mut(), DepthRow::as_mut_ptr);
            call.stencil = stencil.as_mut().map_or(std::ptr::null_mut(), |s| s.as_mut_ptr());
            self.call(&call, u);
            return;
        }
        let mut scratch = Scratch::default();
        scratch.color[..len * bpp].copy_from_slice(color);
        call.color = scratch.color.as_mut_ptr();
        match &depth {
            Some(DepthRow::U16(d)) => {
                scratch.depth16[..len].copy_from_slice(d);
                call.depth = scratch.depth16.as_mut_ptr().cast();
            }
            Some(DepthRow::U32(d)) => {
                scratch.depth32[..len].copy_from_slice(d);
                call.depth = scratch.depth32.as_mut_ptr().cast();
            }
            None => {}
        }
        if let Some(s) = &stencil {
            scratch.stencil[..len].copy_from_slice(s);
            call.stencil = scratch.stencil.as_mut_ptr();
        }
        self.call(&call, u);
        color.copy_from_slice(&scratch.color[..len * bpp]);
        match depth {
            Some(DepthRow::U16(d)) => d.copy_from_slice(&scratch.depth16[..len]),
            Some(DepthRow::U32(d)) => d.copy_from_slice(&scratch.depth32[..len]),
            None => {}
        }
        if let Some(s) = stencil {
            s.copy_from_slice(&scratch.stencil[..len]);
        }
    }

    fn call(&self, call: &SpanCall, u: &FragmentUniforms) {
        // SAFETY: `self.func` was compiled from `self.key`, which `run` checked against
        // the target's formats. The generated code reads the span and the uniforms
        // through these references (and the planes, non-null whenever the key has a
        // shading stage: `check_planes`), and reads and writes `4 * call.groups` pixels
        // from each non-null buffer pointer (and no buffer the key does not use):
        // `run_span` made each pointer from a slice of at least that many pixels. Keys
        // with texture units read `call.tex`, the `TexView` `run_with_planes` made for
        // them and keeps alive across the call, and pass it to `callout::texture_group`
        // with a stack slot of their own.
        unsafe { (self.func)(call, u) }
    }
}

/// `n` depth values of a row, from `index`.
enum DepthRow<'a> {
    U16(&'a mut [u16]),
    U32(&'a mut [u32]),
}

impl DepthRow<'_> {
    fn as_mut_ptr(&mut self) -> *mut u8 {
        match self {
            DepthRow::U16(d) => d.as_mut_ptr().cast(),
            DepthRow::U32(d) => d.as_mut_ptr().cast(),
        }
    }
}

fn depth_row<'a>(d: &'a mut DepthTarget<'_>, index: usize, n: usize) -> Option<DepthRow<'a>> {
    Some(match d {
        DepthTarget::D16(d) => DepthRow::U16(d.get_mut(index..index + n)?),
        DepthTarget::D24(d) | DepthTarget::D32(d) => DepthRow::U32(d.get_mut(index..index + n)?),
    })
}

/// A span's worth of pixels, for spans whose last group crosses the right edge.
struct Scratch {
    color: [u8; SPAN_MAX * 4],
    depth16: [u16; SPAN_MAX],
    depth32: [u32; SPAN_MAX],
    stencil: [u8; SPAN_MAX],
}

impl Default for Scratch {
    fn default() -> Self {
        Scratch {
            color: [0; SPAN_MAX * 4],
            depth16: [0; SPAN_MAX],
            depth32: [0; SPAN_MAX],
            stencil: [0; SPAN_MAX],
        }
    }
}

impl Drop for Specialist {
    fn drop(&mut self) {
        if let Some(module) = self.module.take() {
            // SAFETY: `func` points into this module and is only called through
            // `&self`, so no call can be running or happen after this.
            unsafe { module.free_memory() };
        }
    }
}
