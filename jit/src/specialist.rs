//! A compiled specialist and the one place softgl calls into generated code.

use crate::callout::TexView;
use crate::compile::{self, CompileError, RegAlloc, SpanCall, SpanFn, SpanPlanes, SplatUniforms};
use crate::interp::{check_key, check_planes, FragmentError};
use crate::key::FragmentKey;
use crate::pixel;
use crate::shade::{Planes, COLOUR_BOUNDED};
use crate::span::{FragmentSpan, SPAN_MAX};
use crate::target::{DepthTarget, Target};
use crate::texture::TextureSet;
use crate::tier::{self, Tier};
use crate::uniforms::FragmentUniforms;
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{Module, ModuleError};
use std::cell::RefCell;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, OnceLock, PoisonError, Weak};

/// Fresh Cranelift contexts.
fn contexts() -> (cranelift_codegen::Context, cranelift_frontend::FunctionBuilderContext) {
    (
        cranelift_codegen::Context::new(),
        cranelift_frontend::FunctionBuilderContext::new(),
    )
}

thread_local! {
    /// Each compiling thread's Cranelift contexts, reused from compile to compile.
    static CONTEXTS: RefCell<(cranelift_codegen::Context, cranelift_frontend::FunctionBuilderContext)> =
        RefCell::new(contexts());
}

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

/// The host ISA with register allocator `alloc` ([`compile::host_isa_with`]),
/// made once per process.
fn isa(alloc: RegAlloc) -> Result<&'static OwnedTargetIsa, SpecialistError> {
    static ISAS: [OnceLock<Result<OwnedTargetIsa, String>>; 2] = [OnceLock::new(), OnceLock::new()];
    let slot = match alloc {
        RegAlloc::Backtracking => &ISAS[0],
        RegAlloc::SinglePass => &ISAS[1],
    };
    slot.get_or_init(|| compile::host_isa_with(alloc).map_err(|e| e.to_string()))
        .as_ref()
        .map_err(|e| SpecialistError::Compile(CompileError::Isa(e.clone())))
}

/// The directory of `SOFTGL_JIT_DUMP`, read once: where each compiled
/// specialist's key and machine code go (for profiling the generated code).
fn dump_dir() -> Option<&'static str> {
    static DIR: OnceLock<Option<String>> = OnceLock::new();
    DIR.get_or_init(|| std::env::var("SOFTGL_JIT_DUMP").ok().filter(|d| !d.is_empty()))
        .as_deref()
}

/// Writes a compiled specialist to the `SOFTGL_JIT_DUMP` directory: its
/// key and disassembly in `key-ADDR.txt`, and a line `ADDR SIZE NAME` in
/// `/tmp/perf-PID.map` (the map `perf report` reads for JIT code; the
/// addresses also name the code in callgrind's `--dump-instr=yes` output).
/// Failures to write are ignored: this is a profiling aid only.
fn dump_code(dir: &str, key: &FragmentKey, alloc: RegAlloc, (code, size): (*const u8, u32), text: &str) {
    use std::io::Write;
    let addr = code as usize;
    let name = format!("specialist-{addr:x}-{alloc:?}");
    let _ = std::fs::write(
        format!("{dir}/key-{addr:x}.txt"),
        format!("{name} {size} bytes\n{key:#?}\n{text}"),
    );
    let map = format!("/tmp/perf-{}.map", std::process::id());
    if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open(map) {
        let _ = writeln!(f, "{addr:x} {size:x} {name}");
    }
}

/// `JITModule`s holding code now, in the whole process.
static LIVE_MODULES: AtomicUsize = AtomicUsize::new(0);

/// How many compiled modules hold code now, in the whole process: one per
/// [`Tier::Quick`] or [`Tier::Optimized`] specialist, two per upgraded
/// [`Tier::Tiered`] one, and one while the background thread holds a result.
/// Tests count leaks with it.
pub fn live_modules() -> usize {
    LIVE_MODULES.load(Ordering::Relaxed)
}

/// A finalized `JITModule`, freed on drop. Never reached through a shared
/// reference: only [`Compiled`]'s drop takes it, by value.
struct OwnedModule(Option<JITModule>);

// SAFETY: `JITModule` is not `Sync` because of the `RefCell` symbol table it
// reads while linking; `OwnedModule` has no method taking `&self`, so a shared
// reference to it gives access to nothing. (It is `Send` on its own: Cranelift
// marks the raw pointers it holds — its code and data blobs, its memory
// provider, its symbol addresses — `Send`, and the ISA behind it is an
// `Arc<dyn TargetIsa + Send + Sync>`. So a module finalized on the background
// thread may be moved to the specialist and freed on whichever thread drops it.)
unsafe impl Sync for OwnedModule {}

impl Drop for OwnedModule {
    fn drop(&mut self) {
        if let Some(module) = self.0.take() {
            // SAFETY: an `OwnedModule` lives in a `Compiled`, whose `func` is only
            // called by `Specialist::run_with_planes` through `&Specialist`, and the
            // specialist owns that `Compiled` (as its first code, or in the upgrade
            // slot it holds an `Arc` to, which is never emptied): while the module
            // exists no call can be running, and none happens after this. A result of
            // the background thread that no specialist took was never called.
            unsafe { module.free_memory() };
            LIVE_MODULES.fetch_sub(1, Ordering::Relaxed);
        }
    }
}

/// One compile of a key: its function and the module that holds its code.
struct Compiled {
    func: SpanFn,
    alloc: RegAlloc,
    _module: OwnedModule,
}

/// The optimized code of a [`Tier::Tiered`] specialist, filled in by the
/// background thread, which holds only a `Weak` to it (so a specialist dropped
/// before its upgrade frees everything it has).
struct Upgrade {
    code: Arc<OnceLock<Compiled>>,
    over: Arc<Over>,
}

/// Whether the background thread is done with an upgrade (installed it,
/// skipped it or failed), for [`Specialist::wait_optimized`].
#[derive(Default)]
struct Over {
    done: Mutex<bool>,
    signal: Condvar,
}

/// The background compile of a [`Tier::Tiered`] specialist's optimized code.
/// Dropping it, run or not, marks the upgrade over.
struct UpgradeJob {
    key: FragmentKey,
    code: Weak<OnceLock<Compiled>>,
    over: Arc<Over>,
}

impl UpgradeJob {
    /// Compiles with the backtracking allocator and installs the code, unless
    /// the specialist was dropped before or during the compile (then its code
    /// is freed here).
    fn run(self) {
        if self.code.strong_count() == 0 {
            return;
        }
        let Ok(compiled) = Specialist::compile_code(&self.key, RegAlloc::Backtracking) else {
            return;
        };
        if let Some(slot) = self.code.upgrade() {
            let _ = slot.set(compiled);
        }
    }
}

impl Drop for UpgradeJob {
    fn drop(&mut self) {
        // The job holds no strong reference to the code slot by now, so a
        // specialist dropped after `wait_optimized` frees both modules itself.
        *self.over.done.lock().unwrap_or_else(PoisonError::into_inner) = true;
        self.over.signal.notify_all();
    }
}

/// One key's stages compiled to native code, in a module of its own so that
/// dropping the specialist frees its code pages. A [`Tier::Tiered`] specialist
/// has a second module, its optimized code, once the background thread has
/// compiled it; each call of `run*` reads which code to run once (an acquire
/// load), so a call that started on the first code finishes on it, and both
/// modules live until the specialist drops.
///
/// `Send` and `Sync`: the code is immutable once finalized, and the upgrade
/// slot is a `OnceLock`.
pub struct Specialist {
    key: FragmentKey,
    /// The key's natively sampled units (a bit mask) and whether its code
    /// reads [`COLOUR_BOUNDED`] (`compile::reads_colour_bound`): found once
    /// here, not once a batch (some 50 instructions each).
    units: u32,
    colour_bound: bool,
    first: Compiled,
    upgrade: Option<Upgrade>,
}

const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<Specialist>();
};

impl std::fmt::Debug for Specialist {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Specialist")
            .field("key", &self.key)
            .field("optimized", &self.is_optimized())
            .finish_non_exhaustive()
    }
}

/// The [`SpanPlanes`] entry of a primitive's planes `p` for code that
/// samples `units` natively and, with `bound` (the extent of the pixels it
/// shades), reads [`COLOUR_BOUNDED`]. Not inlined: made once a primitive,
/// it kept the per-span loop that copies it from being as tight (the
/// `fill` frame's caller took 3 M instructions more inlined).
#[inline(never)]
fn span_planes(p: Option<&Planes>, units: u32, bound: Option<u32>) -> SpanPlanes {
    let Some(p) = p else {
        return SpanPlanes {
            planes: std::ptr::null(),
            ones: 0,
            _pad: 0,
        };
    };
    let mut ones = p.ones(units);
    if bound.is_some_and(|e| ones & 1 != 0 && p.colour_bounded(e)) {
        ones |= COLOUR_BOUNDED;
    }
    SpanPlanes {
        planes: p,
        ones,
        _pad: 0,
    }
}

impl Specialist {
    /// Compiles `key` in the tier [`Tier::for_key`] picks: keys with texture
    /// units [`Tier::Tiered`], others [`Tier::Optimized`]. A panic inside
    /// Cranelift is caught and returned as an error.
    pub fn compile(key: &FragmentKey) -> Result<Specialist, SpecialistError> {
        Self::compile_tier(key, Tier::for_key(key))
    }

    /// Compiles `key` in `tier`. For [`Tier::Tiered`] this returns once the
    /// quick code is ready and queues the optimized compile on the background
    /// thread (if that thread cannot run, the specialist keeps its quick code).
    pub fn compile_tier(key: &FragmentKey, tier: Tier) -> Result<Specialist, SpecialistError> {
        key.validate()?;
        let first = Self::compile_code(key, tier.first())?;
        let upgrade = (tier == Tier::Tiered).then(|| {
            let upgrade = Upgrade {
                code: Arc::new(OnceLock::new()),
                over: Arc::new(Over::default()),
            };
            let job = UpgradeJob {
                key: *key,
                code: Arc::downgrade(&upgrade.code),
                over: upgrade.over.clone(),
            };
            // Not queued: dropping the job marks the upgrade over.
            let _ = tier::background(Box::new(move || job.run()));
            upgrade
        });
        let units = key.shade.as_ref().map_or(0, |s| {
            (0..crate::texture::MAX_UNITS)
                .filter(|&u| s.tex[u].as_ref().is_some_and(compile::native_unit))
                .map(|u| 1 << u)
                .sum()
        });
        Ok(Specialist {
            key: *key,
            units,
            colour_bound: compile::reads_colour_bound(key),
            first,
            upgrade,
        })
    }

    /// Compiles a valid `key` with `alloc` into a module of its own, catching a
    /// panic inside Cranelift.
    fn compile_code(key: &FragmentKey, alloc: RegAlloc) -> Result<Compiled, SpecialistError> {
        let isa = isa(alloc)?;
        catch_unwind(AssertUnwindSafe(|| Self::compile_with(key, isa, alloc))).unwrap_or_else(|p| {
            // A panic may have left the thread's contexts half used: new ones.
            CONTEXTS.set(contexts());
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(SpecialistError::Panic(msg))
        })
    }

    fn compile_with(key: &FragmentKey, isa: &OwnedTargetIsa, alloc: RegAlloc) -> Result<Compiled, SpecialistError> {
        let mut module = JITModule::new(JITBuilder::with_isa(
            isa.clone(),
            cranelift_module::default_libcall_names(),
        ));
        let built = CONTEXTS.with_borrow_mut(|(ctx, fctx)| -> Result<*const u8, Box<ModuleError>> {
            // The thread's contexts, cleared: their buffers (the register
            // allocator's above all) are reused rather than allocated again.
            ctx.clear();
            ctx.func.signature = compile::signature(isa);
            // The quick tier samples through the callout: its code is a
            // fraction of the native sampler's, compiled in a fraction of the time.
            let native_sampling = alloc == RegAlloc::Backtracking;
            compile::build_with(key, isa, &mut ctx.func, (fctx, native_sampling));
            let id = module.declare_anonymous_function(&ctx.func.signature)?;
            let dump = dump_dir();
            ctx.set_disasm(dump.is_some());
            module.define_function(id, ctx)?;
            module.finalize_definitions()?;
            let code = module.get_finalized_function(id);
            if let Some(dir) = dump {
                let size = ctx.compiled_code().map_or(0, |c| c.code_info().total_size);
                let text = ctx.compiled_code().and_then(|c| c.vcode.clone()).unwrap_or_default();
                dump_code(dir, key, alloc, (code, size), &text);
            }
            Ok(code)
        });
        match built {
            Ok(code) => {
                // SAFETY: `code` is the finalized function built with `compile::signature`,
                // which is `SpanFn`'s ABI (two pointers, no result, the ISA's default
                // convention), and it lives as long as `module`, which the returned
                // `Compiled` owns.
                let func = unsafe { std::mem::transmute::<*const u8, SpanFn>(code) };
                LIVE_MODULES.fetch_add(1, Ordering::Relaxed);
                Ok(Compiled {
                    func,
                    alloc,
                    _module: OwnedModule(Some(module)),
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

    /// The code `run*` calls now: the optimized code once installed, else the first.
    fn code(&self) -> &Compiled {
        self.upgrade.as_ref().and_then(|u| u.code.get()).unwrap_or(&self.first)
    }

    /// Whether the code run now was compiled with the backtracking register
    /// allocator ([`Tier::Optimized`], or [`Tier::Tiered`] once upgraded).
    pub fn is_optimized(&self) -> bool {
        self.code().alloc == RegAlloc::Backtracking
    }

    /// Whether this is a [`Tier::Tiered`] specialist whose optimized code is installed.
    pub fn is_upgraded(&self) -> bool {
        self.upgrade.as_ref().is_some_and(|u| u.code.get().is_some())
    }

    /// Blocks until the optimized code of a [`Tier::Tiered`] specialist is
    /// installed, or its compile failed; returns at once for the other tiers.
    /// For tests and benches: a draw never waits for it.
    pub fn wait_optimized(&self) {
        if let Some(u) = &self.upgrade {
            let done = u.over.done.lock().unwrap_or_else(PoisonError::into_inner);
            drop(
                u.over
                    .signal
                    .wait_while(done, |done| !*done)
                    .unwrap_or_else(PoisonError::into_inner),
            );
        }
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
        let view = self.texture_view(textures);
        self.run_splatted(&SplatUniforms::new(uniforms), (textures, &view), spans, planes, target)
    }

    /// What this specialist reads of a draw's `textures`, made once for all
    /// the draw's spans ([`Self::run_splatted`]).
    pub fn texture_view<'a>(&'a self, textures: &'a TextureSet<'a>) -> DrawTextures<'a> {
        match self.key.shade.as_ref().filter(|s| s.textured()) {
            Some(shade) => match TexView::new(&shade.tex, textures) {
                Some(view) => DrawTextures::View(Box::new(view)),
                None => DrawTextures::Interpreter,
            },
            None => DrawTextures::None,
        }
    }

    /// [`Self::run_with_planes`] with the view of `textures` made by
    /// [`Self::texture_view`] and the uniforms splatted, both once for a draw,
    /// not once a batch (a flush runs a batch per tile a small triangle
    /// touches: `thrash`, 112 instructions a batch).
    pub fn run_splatted(
        &self,
        splats: &SplatUniforms,
        (textures, view): (&TextureSet<'_>, &DrawTextures<'_>),
        spans: &[FragmentSpan],
        planes: &[Planes],
        target: &mut Target<'_>,
    ) -> Result<(), FragmentError> {
        let uniforms = &splats.uniforms;
        check_key(&self.key, target)?;
        check_planes(&self.key, spans, planes)?;
        let units = self.key.shade.as_ref().filter(|s| s.textured()).map(|s| &s.tex);
        let tex = match (units, view) {
            (None, _) => std::ptr::null(),
            (Some(units), DrawTextures::View(v)) if v.is_for(units) => (&**v as *const TexView<'_>).cast(),
            // A natively sampled unit without a texture it can read.
            (Some(_), DrawTextures::Interpreter) => {
                return crate::interp::run_with_planes(&self.key, uniforms, textures, spans, planes, target)
            }
            // Not this key's view: the generated code reads only its own.
            (Some(_), _) => {
                let own = self.texture_view(textures);
                return self.run_splatted(splats, (textures, &own), spans, planes, target);
            }
        };
        let func = self.code().func;
        // The batch runs in one call (a chunk of `CHUNK` spans a call): the
        // generated code finds each span's live lanes and pixels from the
        // target's geometry (`SpanCall`), and takes each span's planes and
        // their exactly-1 flags (`SpanPlanes`) from a table made here once a
        // primitive. Per span, the call and its record cost 113 + 25
        // instructions outside the groups where this costs about 35
        // (module docs of `compile`).
        let lay = target.layout();
        let parts = target.raw_parts();
        let units = self.units;
        // Row 0 of the view (the step to the next row up is `stride`).
        let row0 = |color: *mut u8| {
            if lay.top_down {
                color.wrapping_add(lay.rows.saturating_sub(1) as usize * lay.stride)
            } else {
                color
            }
        };
        let mut call = SpanCall {
            spans: std::ptr::null(),
            count: 0,
            next: 0,
            color: row0(parts.color),
            stride: if lay.top_down {
                (lay.stride as i64).wrapping_neg()
            } else {
                lay.stride as i64
            },
            depth: parts.depth,
            stencil: parts.stencil,
            width: lay.width,
            y0: lay.y0,
            rows: lay.rows,
            height: lay.height,
            dither: [0; 4],
            planes: std::ptr::null(),
            tex,
            passed: 0,
        };
        // Whether every pixel of the view's rows is inside its buffers: then
        // so is every group the code runs (a span's groups end at or before
        // the view's width). Else (and for keys that dither, whose bias is
        // the span's) one span a call, from checked slices.
        let fits = lay.fits(&parts) && !self.key.dither;
        // For keys whose code asks (`compile::reads_colour_bound`), whether
        // each primitive's colour is bounded at the pixels the code shades:
        // `px` below the width (plus a group's overhang), `row` below the height.
        let bound = self
            .colour_bound
            .then(|| lay.width.saturating_add(SPAN_MAX as u32).max(lay.height));
        let mut table = [SpanPlanes {
            planes: std::ptr::null(),
            ones: 0,
            _pad: 0,
        }; CHUNK];
        let mut last = None;
        let mut entry = table[0];
        for chunk in spans.chunks(CHUNK) {
            if self.key.shade.is_some() {
                // The planes change with the primitive, not with every span.
                for (t, span) in table.iter_mut().zip(chunk) {
                    if last != Some(span.planes) {
                        last = Some(span.planes);
                        entry = span_planes(planes.get(span.planes as usize), units, bound);
                    }
                    *t = entry;
                }
                call.planes = table.as_ptr();
            }
            call.spans = chunk.as_ptr();
            call.count = chunk.len() as u32;
            let mut next = 0;
            while next < chunk.len() {
                if fits {
                    call.next = next as u32;
                    self.call(func, &mut call, splats);
                    next = call.next as usize;
                    if next >= chunk.len() {
                        break;
                    }
                }
                // The span's last group crosses the right edge (or the batch
                // runs a span a call): from checked slices, on a copy if so.
                let Some(span) = chunk.get(next) else { break };
                let passed = self.run_span(func, (splats, &call), (span, table[next]), target);
                call.passed += passed;
                // (`run_span` borrowed the buffers again.)
                let parts = target.raw_parts();
                (call.color, call.depth, call.stencil) = (row0(parts.color), parts.depth, parts.stencil);
                next += 1;
            }
        }
        target.add_samples_passed(call.passed);
        Ok(())
    }

    /// Runs `func` over `span` alone (`batch`: the batch's call, for its
    /// textures), whose pixels are taken from checked slices of `t`: in
    /// place, or when its last group crosses the right edge on a copy of
    /// the row's end padded to whole groups. The call's target is made to
    /// look like a one-row view whose row starts at the pixels (pointers
    /// offset back by `span.x` pixels, which the code adds again).
    fn run_span(
        &self,
        func: SpanFn,
        (u, batch): (&SplatUniforms, &SpanCall),
        (span, entry): (&FragmentSpan, SpanPlanes),
        t: &mut Target<'_>,
    ) -> u64 {
        let live = t.owned_mask(span);
        if live == 0 {
            return 0;
        }
        let groups = (64 - live.leading_zeros()).div_ceil(4);
        let n = 4 * groups as usize;
        // `owned_mask` is zero for spans at or right of the width.
        let inside = (t.width() - span.x).min(SPAN_MAX as u32) as usize;
        // The span with its live lanes only (the code clips nothing more).
        let mut one = span.clone();
        one.mask = live;
        one.len = SPAN_MAX as u32;
        let entry = [entry];
        let x = span.x as usize;
        let mut call = SpanCall {
            spans: &one,
            count: 1,
            next: 0,
            color: std::ptr::null_mut(),
            stride: 0,
            depth: std::ptr::null_mut(),
            stencil: std::ptr::null_mut(),
            width: span.x + n as u32,
            y0: span.y,
            rows: 1,
            height: t.height(),
            dither: [0; 4],
            planes: if batch.planes.is_null() {
                std::ptr::null()
            } else {
                entry.as_ptr()
            },
            tex: batch.tex,
            passed: 0,
        };
        if self.key.dither {
            call.dither = std::array::from_fn(|i| pixel::dither_bias(span.x + i as u32, span.y));
        }
        let bpp = self.key.color_format.bytes_per_pixel();
        let color_at = t.color_offset(span.x, span.y);
        let index = t.index(span.x, span.y);
        let (color, depth, stencil) = t.parts_mut();
        // Whole groups inside the row are run in place; when the last group
        // crosses the right edge, on a copy of the row's end padded to whole groups.
        let len = n.min(inside);
        let Some(color) = color.get_mut(color_at..color_at + len * bpp) else {
            return 0;
        };
        let mut depth = match depth {
            Some(d) => match depth_row(d, index, len) {
                Some(row) => Some(row),
                None => return 0,
            },
            None => None,
        };
        let mut stencil = match stencil {
            Some(s) => match s.get_mut(index..index + len) {
                Some(row) => Some(row),
                None => return 0,
            },
            None => None,
        };
        // Each buffer's pointer `x` elements before the span's first pixel.
        let back = |p: *mut u8, size: usize| if p.is_null() { p } else { p.wrapping_sub(x * size) };
        let dsize = |d: &DepthRow| match d {
            DepthRow::U16(_) => 2,
            DepthRow::U32(_) => 4,
        };
        if n <= inside {
            call.color = back(color.as_mut_ptr(), bpp);
            call.depth = depth
                .as_mut()
                .map_or(std::ptr::null_mut(), |d| back(d.as_mut_ptr(), dsize(d)));
            call.stencil = stencil
                .as_mut()
                .map_or(std::ptr::null_mut(), |s| back(s.as_mut_ptr(), 1));
            self.call(func, &mut call, u);
            return call.passed;
        }
        let mut scratch = Scratch::default();
        // The deep formats' wider pixels in a buffer of their own, so that
        // the other formats' spans (every span of a dithering key) zero
        // only a quarter of it.
        let mut deep_color;
        let scratch_color: &mut [u8] = if bpp > 4 {
            deep_color = [0u8; SPAN_MAX * MAX_BYTES_PER_PIXEL];
            &mut deep_color
        } else {
            &mut scratch.color
        };
        scratch_color[..len * bpp].copy_from_slice(color);
        call.color = back(scratch_color.as_mut_ptr(), bpp);
        call.depth = match &depth {
            Some(DepthRow::U16(d)) => {
                scratch.depth16[..len].copy_from_slice(d);
                back(scratch.depth16.as_mut_ptr().cast(), 2)
            }
            Some(DepthRow::U32(d)) => {
                scratch.depth32[..len].copy_from_slice(d);
                back(scratch.depth32.as_mut_ptr().cast(), 4)
            }
            None => std::ptr::null_mut(),
        };
        call.stencil = match &stencil {
            Some(s) => {
                scratch.stencil[..len].copy_from_slice(s);
                back(scratch.stencil.as_mut_ptr(), 1)
            }
            None => std::ptr::null_mut(),
        };
        self.call(func, &mut call, u);
        color.copy_from_slice(&scratch_color[..len * bpp]);
        match depth {
            Some(DepthRow::U16(d)) => d.copy_from_slice(&scratch.depth16[..len]),
            Some(DepthRow::U32(d)) => d.copy_from_slice(&scratch.depth32[..len]),
            None => {}
        }
        if let Some(s) = stencil {
            s.copy_from_slice(&scratch.stencil[..len]);
        }
        call.passed
    }

    /// Calls `func`, which is [`Self::code`]'s function, read once for the whole `run*` call.
    fn call(&self, func: SpanFn, call: &mut SpanCall, u: &SplatUniforms) {
        // SAFETY: `func` is the code of one of this specialist's `Compiled`s, both
        // compiled from `self.key`, which `run_splatted` checked against the target's
        // formats; `&self` keeps its module alive across the call (`OwnedModule`'s
        // drop). The generated code reads the spans `call.spans[next..count]` and the
        // uniforms through these references, writes only `call.next`, and reads each
        // span's `SpanPlanes` entry (non-null whenever the key has a shading stage,
        // and then each entry's planes too: `check_planes`). It writes the pixels of
        // a span's groups only when they lie in the view's rows `y0..y0 + rows` and
        // columns `0..width`, at the offsets `Target::color_offset` and `Target::index` give from the
        // buffer pointers: `run_splatted` passes the target's `raw_parts` (taken
        // after any `run_span` borrowed the buffers again) only when
        // `Layout::fits` found every such pixel inside each buffer, and
        // `run_span` passes a one-row view of `n` columns from `span.x` whose
        // pointers, offset back by `span.x` elements (wrapping), point at a
        // checked slice of at least `n` elements (or null, for a buffer the key
        // does not use). Keys with texture units read `call.tex`, a `TexView`
        // made for their units (`run_splatted` checked `is_for`) and alive across
        // the call, and pass it to `callout::texture_group` with a stack slot of
        // their own.
        unsafe { func(call, u) }
    }
}

/// Spans a call of the generated code takes at most (the `SpanPlanes` table
/// is on the stack): a `FragmentStage` batch.
const CHUNK: usize = 32;

/// A draw's textures as a specialist reads them ([`Specialist::texture_view`]).
pub enum DrawTextures<'a> {
    /// The key samples no texture.
    None,
    /// The view of the draw's textures (boxed: it is 4 KB).
    View(Box<TexView<'a>>),
    /// A natively sampled unit has no texture it can read: the draw runs on
    /// the interpreter.
    Interpreter,
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
        DepthTarget::D24(d) | DepthTarget::D32(d) | DepthTarget::D32F(d) => DepthRow::U32(d.get_mut(index..index + n)?),
    })
}

/// The widest pixel: `ColorFormat::Rgba32F`'s.
const MAX_BYTES_PER_PIXEL: usize = 16;

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
