//! The Cranelift compiler: a [`FragmentKey`] becomes one native function that
//! runs the key's stages over one span, four fragments at a time.
//!
//! Every fragment value lives in an `i32x4` (one lane per fragment): colors as
//! bytes `0..=255`, depth as the stored integer, stencil as a byte. Tests produce
//! lane masks (all ones or all zeros) that narrow the live mask; writes select
//! between the new and the stored value with the live mask, so no fragment takes
//! a branch of its own. A group of four whose live lanes all die skips the rest
//! of the stages. x86-64 Cranelift has 128-bit vectors only, so four 32-bit lanes
//! is the widest group that keeps depth in one register.
//!
//! Per-group costs, measured on the machine code (`disasm` test below) and
//! with callgrind on `osmesa/bench/fill.c`, one thread: the live mask is made
//! only when a stage needs it, so a key without tests stores a group whose
//! four lanes are live without reading the pixels; lane selects are
//! `blendvps`; constants come from the constant pool; blending runs two
//! channels a vector in `u16` lanes. The `fill` frame's specialist went from
//! 73.7 to 66.0 instructions a group of four (the frame: 24.7 -> 22.8 a
//! fragment), the `ops` frame's specialists from 872 M to 650 M instructions
//! a frame (the frame: 1597 M -> 1375 M).
//!
//! Then (issue 13; callgrind, `fill.c CASE 1` runs of two frames, one
//! thread, `SOFTGL_JIT_TIER=optimized`; specialists' own instructions):
//! - a span whose 1/w plane is exactly 1 (every `glOrtho` or untransformed
//!   draw) takes the colours and texture coordinates from the planes
//!   without dividing by 1/w or q (`shade::perspective`, `plain_coords`:
//!   bit for bit what the division gives, see `Planes::is_one`);
//! - the plane loads come in the order Cranelift folds one into its
//!   fused multiply-add (4 instructions a plane, was 5);
//! - untextured alpha is shaded alone for the alpha test, the other
//!   channels only for groups the stencil and depth tests leave;
//! - the scissor's columns narrow the span's live bits once (no test a
//!   group), and the stages' integer uniforms come splatted
//!   ([`SplatUniforms`]): one vector load each, was load, move, splat.
//!
//! `fill` 553.7 M -> 439.3 M (the `fill` group: 66 -> 52 instructions),
//! `ops` 1300 M -> 912 M, `xor` 1226 M -> 837 M, `tex` 1935 M -> 1750 M
//! (with the fog changes in `shade`); the frames' times against llvmpipe,
//! one thread (`compare.sh 3`, one run): `fill` 1.04 -> 0.70, `ops` 1.17 ->
//! 0.99, `xor` 1.25 -> 1.01, `tex` 1.18 -> 1.09.
//! The price is compile time: the short paths are a branch and a second
//! arm (release build, `compile_time` test below, medians on the loaded
//! 2-core machine: `fill` 123 -> ~150 µs, `ops` 291 -> ~350 µs; the
//! 256-key `thrash-first` frame stays about 1/30 of llvmpipe's).
//!
//! Then (issue 13, fourth session; same method, `fill.c CASE 1` and `CASE 3`
//! runs, the difference halved: a frame's instructions): whether the 1/w
//! and q/w planes are exactly 1 comes from the caller once a primitive
//! (`SpanPlanes::ones`, `Planes::ones`) rather than from six plane loads a
//! span; untextured keys keep the unorm8 conversion's 255.0 in a register
//! across the span; textured keys make zero where it is used (kept for the
//! group it was spilled); and the caller's per-span path reads the target
//! once a batch (`Specialist::run_splatted`). `fill` 282.5 M -> 272.4 M
//! a frame (16.84 -> 16.24 instructions a fragment; its specialist 52.4 ->
//! 51.1 a group), `tex` 1318.8 M -> 1268.8 M (its specialists 824 -> 791 M).
//! Tried and dropped: each bilinear row's two texels as one 8-byte load
//! (8 loads a level where 16 are made now): the pair vectors feed two
//! shuffles, so Cranelift folds none of the loads (it folds a load into a
//! single use only), and a textured group took 513 instructions where it
//! takes 521, for a second gather path in every bilinear level;
//! the loop made twice for untextured keys, for w exactly 1 and any w (two
//! instructions fewer a group): Cranelift then folded no plane's `a0` into
//! its multiply-add (5 instructions a plane, not 4), which cost more.
//!
//! Then (fifth session; callgrind, `fill.c CASE 1`, one thread,
//! `SOFTGL_JIT_TIER=optimized`: two frames): one call runs a batch of
//! spans (up to 32, a `FragmentStage` batch) instead of one. The code finds
//! each span's live lanes (`Target::owned_mask`) and its pixels from the
//! target's geometry in [`SpanCall`], and its planes and their exactly-1
//! flags from a table ([`SpanPlanes`]) the caller fills once a primitive;
//! a span whose last group crosses the view's right edge stops the batch
//! and the caller runs it on a copy. Per span, the caller's record, the
//! call and the function's entry took about 150 instructions (113 in
//! `run_splatted`, 25–42 in the entry and exit); now about 80 in the
//! generated code and 25 in the caller. The top-down flip comes folded
//! into the colour pointer and a negative stride (five instructions a
//! span). `tex` 2627.6 M -> 2550.6 M (its 2.41 M spans), `fill` 598.7 M
//! -> 584.5 M. Tried and dropped: the batch's geometry (spans, y0, rows,
//! width) loaded once in the entry block rather than once a span: the
//! textured key spilled and reloaded them around the group loop's callout
//! (`tex` +13 M), `fill` gained 0.5 M.
//!
//! Then (sixth session; callgrind, `fill.c fill 1`, one thread,
//! `SOFTGL_JIT_TIER=optimized`: two frames, the specialist's own
//! instructions): keys that test no lane and sample no texture run a span's
//! leading full groups in a loop of their own ([`Gen::full_groups`]), two
//! groups a turn, where the span's 1/w plane is exactly 1: no live bits to
//! shift and test, no test of w, the store with no choice, one compare a
//! turn. Where the primitive's colour is bounded (`Planes::colour_bounded`,
//! a bit of [`SpanPlanes::ones`] the caller sets for keys that read it,
//! [`reads_colour_bound`]) the unorm8 conversion leaves out its clamp to
//! 255 (the saturating narrowings clamp). The pixels' interleave is one
//! `pshufb` whose mask stays in a register: with `shuffle` of one value
//! twice, or the clamp's two reads of a value, Cranelift folds no load of
//! the values it is made from (`compute_use_states` counts every use of
//! a value made from a load; a block parameter with one predecessor does
//! not stop the count, `remove_constant_phis` removes it), so each plane's
//! `a0` took a load of its own. The `fill` group: 49 -> 35.5 instructions
//! (4 a plane, 3 a channel's conversion, 4 to pack, a store, 2.5 of the
//! loop); the specialist 457.4 M -> 349.9 M, the frame 15.8 -> 12.5
//! instructions a fragment (`instructions.sh fill`). Spans of other keys,
//! and the groups after a span's first partial one, take the loop above.
//! The price is compile time for those keys only (a second copy of the
//! group's stages, two in the loop): the `fill` key 250 -> ~450 µs
//! (`compile_time` below, loaded machine); the `thrash` frame's keys all
//! test depth and are unchanged.
//!
//! Then (helper `jitcode`; callgrind with `--dump-instr=yes` and the
//! `SOFTGL_JIT_DUMP` map of each specialist's code, `shadow_fbo.c 1
//! 640x480 plane`, one thread, `SOFTGL_JIT_TIER=optimized`): the MuJoCo
//! shadow maps' depth-only key (D24, `GEQUAL`, writes, no colour) was a
//! third of the MuJoCo frame's instructions. Keys whose only test is
//! depth (or a stencil test that always passes) now run the loop over
//! full groups: the pass mask is the compare (no live mask loaded and
//! applied); a depth test that is the key's last stage writes
//! `max`/`min(z, stored)` for the ordering functions (one `pmaxsd` for
//! the compare, the `pand` and the `blendvps`) and asks no `ptest`;
//! `GEQUAL`/`GREATER` then need no floor at 0 on the converted depth;
//! keys that shade depth alone keep the depth plane's three coefficients,
//! the bound and zero in registers for the span. The depth-only full
//! group: 29 -> 13.5 instructions; the key 585.7 M -> 336.1 M (34.7 ->
//! 19.9 a group of four with the span's ~84). The light passes'
//! per-sample half (colour from the span, `ONE, ONE`): the span's colour
//! is read after the depth test, each channel's four bytes one load into
//! a lane and one `pshufb` ([`Gen::span_packed`]), and `ONE, ONE` with
//! `FUNC_ADD` is one saturating byte add (`paddusb`) of the packed
//! pixels: that key 98.9 M -> 72.2 M. The whole run: 2104 M -> 1827 M.
//!
//! The function reads and writes whole groups of four pixels of the spans it
//! runs: the caller (the `specialist` module) guarantees that every pixel of
//! the view's rows `y0..y0 + rows` and columns `0..width` is addressable
//! from the pointers in [`SpanCall`] at the offsets it computes, and the
//! code runs a span only when its groups end inside those columns.

use crate::key::{
    AlphaCoverage, BlendEquation, BlendFactor, BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey,
    FragmentKey, LogicOp, Stage, StencilKey, StencilOp,
};
use crate::pixel;
use crate::shade::{Planes, COLOUR_BOUNDED};
use crate::span::{FragmentSpan, SPAN_MAX};
use crate::uniforms::FragmentUniforms;
use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::immediates::V128Imm;
use cranelift_codegen::ir::{types, AbiParam, Block, BlockArg, InstBuilder, MemFlagsData, Signature, Type, Value};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use std::mem::{offset_of, size_of};

mod deep;
mod sample;
mod shade;
mod texture;

pub use sample::{native_sampler, native_unit};

const I32X4: Type = types::I32X4;

/// The lane mask of each group's four live bits: lane `i` all ones where bit `i` is set.
#[repr(align(16))]
struct LiveMasks([[u32; 4]; 16]);

static LIVE_MASKS: LiveMasks = LiveMasks({
    let mut t = [[0u32; 4]; 16];
    let mut bits = 0;
    while bits < 16 {
        let mut i = 0;
        while i < 4 {
            if bits & (1 << i) != 0 {
                t[bits][i] = u32::MAX;
            }
            i += 1;
        }
        bits += 1;
    }
    t
});

/// What the compiled function is given: a batch of spans and the target
/// they are written into. `#[repr(C)]`: the generated code reads its fields
/// at their `offset_of!` offsets.
///
/// The code runs `spans[next..count]` in order, each span's pixels found
/// from the target's geometry here (as `Target::offsets` finds them), and
/// stores in `next` the first span it did not run: `count`, or a span whose
/// last group of four crosses the view's right edge (the caller runs that
/// one on a copy of its pixels and calls again from the span after it).
#[repr(C)]
#[derive(Debug)]
pub struct SpanCall {
    pub spans: *const FragmentSpan,
    pub count: u32,
    /// In: the first span to run; out: the first span not run.
    pub next: u32,
    /// The colour of pixel `(0, y0)`; row `y0 + r` is `r · stride` bytes
    /// from it (`stride` is negative for a top-down target: the caller
    /// folds the flip in, five instructions a span fewer).
    pub color: *mut u8,
    pub stride: i64,
    /// The depth value (`u16` or `u32`) of pixel `(0, y0)` (rows of
    /// `width` values, bottom up), or null.
    pub depth: *mut u8,
    /// The stencil value of pixel `(0, y0)` (as depth), or null.
    pub stencil: *mut u8,
    /// The view's width, its rows `y0..y0 + rows` and the whole target's
    /// height (for the planes' row).
    pub width: u32,
    pub y0: u32,
    pub rows: u32,
    pub height: u32,
    /// The dither bias of lanes `0..4` (the pattern repeats every four
    /// pixels; a key that dithers is given one span a call).
    pub dither: [u32; 4],
    /// Each span's planes and their exactly-1 flags (keys with a shading
    /// stage; [`SpanPlanes`]), indexed like `spans`, or null.
    pub planes: *const SpanPlanes,
    /// The draw's textures (keys with texture units), or null.
    pub tex: *const crate::callout::TexView<'static>,
    /// Keys that count ([`FragmentKey::count`]): the fragments that passed
    /// every test, added to by each group.
    pub passed: u64,
}

/// A span's primitive's planes, for the generated code ([`SpanCall::planes`]).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct SpanPlanes {
    pub planes: *const Planes,
    /// [`Planes::ones`] of those planes for the key's natively sampled
    /// units: which planes are exactly 1, found once a primitive rather
    /// than once a span.
    pub ones: u32,
    pub _pad: u32,
}

/// The signature of a compiled specialist.
pub type SpanFn = unsafe extern "C" fn(call: *mut SpanCall, uniforms: *const SplatUniforms);

/// Why a key could not be compiled.
#[derive(Debug, thiserror::Error)]
pub enum CompileError {
    #[error("no Cranelift back end for this CPU: {0}")]
    Isa(String),
    #[error("Cranelift rejected the specialist: {0}")]
    Module(#[from] Box<cranelift_module::ModuleError>),
}

/// Cranelift's register allocators (its `regalloc_algorithm` flag).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RegAlloc {
    /// Range splitting and backtracking: slower to compile, code that spills little.
    Backtracking,
    /// One linear pass: compiles in about a third of the time, code that spills a lot.
    SinglePass,
}

/// The host ISA with the flags specialists are compiled with, and the
/// backtracking register allocator ([`host_isa_with`]).
pub fn host_isa() -> Result<OwnedTargetIsa, CompileError> {
    host_isa_with(RegAlloc::Backtracking)
}

/// The host ISA with the flags specialists are compiled with and register
/// allocator `alloc`.
///
/// `opt_level=none`: the generator already emits each constant and factor once
/// per group, so Cranelift's e-graph pass bought only 2% of run time for 50%
/// more compile time (all-ops key on this 2-core machine: 204 µs and 430
/// Mfragments/s without it, 309 µs and 440 with it; the register allocator is
/// most of what is left). The IR verifier runs only in debug builds (it adds 30-60%).
///
/// The register allocator is 74% of a backtracking compile. Single-pass code
/// spills more and runs slower: with an earlier texture generator (per-lane
/// loops) it spilled five times as often and sampled at half the rate; with
/// today's it is 5–10% slower (`jit/benches/texels.rs`, `jit` against
/// `jit_quick`). Hence the tiering policy of
/// [`crate::specialist::Specialist::compile`]: a key with texture units is
/// compiled quick first (the draw waits only for that), then again with
/// native sampling and the backtracking allocator on one background thread,
/// and the specialist switches to that code once it is ready; keys without
/// texture units compile once, backtracking. The quick code samples every
/// unit through the callout
/// ([`build_with`]): what a draw then waits for, against what the background
/// thread spends (`benches/specialists.rs`, group `compile`, criterion
/// medians): one NEAREST unit 88.5 / 249 µs, bilinear 87.4 / 414 µs,
/// trilinear 88.1 / 956 µs, two trilinear units 90.9 µs / 1.69 ms.
pub fn host_isa_with(alloc: RegAlloc) -> Result<OwnedTargetIsa, CompileError> {
    let mut flags = settings::builder();
    let set = |f: &mut settings::Builder, k: &str, v: &str| f.set(k, v).map_err(|e| CompileError::Isa(e.to_string()));
    set(&mut flags, "opt_level", "none")?;
    set(
        &mut flags,
        "enable_verifier",
        if cfg!(debug_assertions) { "true" } else { "false" },
    )?;
    set(&mut flags, "is_pic", "false")?;
    set(
        &mut flags,
        "regalloc_algorithm",
        match alloc {
            RegAlloc::Backtracking => "backtracking",
            RegAlloc::SinglePass => "single_pass",
        },
    )?;
    let isa = cranelift_native::builder().map_err(|e| CompileError::Isa(e.to_string()))?;
    isa.finish(settings::Flags::new(flags))
        .map_err(|e| CompileError::Isa(e.to_string()))
}

/// The signature of [`SpanFn`] for `isa`.
pub fn signature(isa: &OwnedTargetIsa) -> Signature {
    let ptr = isa.pointer_type();
    let mut sig = Signature::new(isa.default_call_conv());
    sig.params.push(AbiParam::new(ptr));
    sig.params.push(AbiParam::new(ptr));
    sig
}

/// Whether `key`'s code reads [`COLOUR_BOUNDED`] of `SpanPlanes::ones`:
/// its loop over full groups runs only where the colour is bounded and
/// converts it without the clamp to 255 ([`SpanValues::colour_bounded`]).
/// Keys whose packed pixels are their primary colour as the planes give it
/// (smooth, no colour sum, fog or texture, packed by the shading stage) and
/// which test no lane.
pub fn reads_colour_bound(key: &FragmentKey) -> bool {
    Gen::full_loop_of(key)
        && Gen::packs_from_shade_of(key)
        && key
            .shade
            .is_some_and(|s| s.color && !s.flat && !s.color_sum && s.fog.is_none() && !s.textured())
}

/// Builds the body of `key`'s specialist into `func` (whose signature is [`signature`]).
/// The key must be valid ([`FragmentKey::validate`]).
pub fn build(key: &FragmentKey, isa: &OwnedTargetIsa, func: &mut cranelift_codegen::ir::Function) {
    build_with(key, isa, func, (&mut FunctionBuilderContext::new(), true));
}

/// [`build`] with a builder context of the caller's (reused from one compile
/// to the next, its buffers are not allocated again), and the texture units
/// sampled natively (`native_sampling`, [`native_unit`]) or all through the
/// reference sampler's callout (the quick tier's code: a fraction of the IR).
pub fn build_with(
    key: &FragmentKey,
    isa: &OwnedTargetIsa,
    func: &mut cranelift_codegen::ir::Function,
    (fctx, native_sampling): (&mut FunctionBuilderContext, bool),
) {
    let b = FunctionBuilder::new(func, fctx);
    let mut g = Gen::new(key, isa.pointer_type(), b);
    g.native_sampling = native_sampling;
    // Specialists are compiled for the host (`host_isa`).
    g.x86 = cfg!(target_arch = "x86_64");
    g.emit();
    g.b.seal_all_blocks();
    g.b.finalize(isa.frontend_config());
}

/// Whether `b` is `ONE, ONE` with `FUNC_ADD` for colour and alpha (the
/// additive light passes): `min(s + d, 255)` a channel.
fn is_add_ones(b: &BlendKey) -> bool {
    let one = BlendFactor::One;
    [b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha] == [one; 4]
        && b.eq_rgb == BlendEquation::Add
        && b.eq_alpha == BlendEquation::Add
}

/// Loads that may not trap (the caller guarantees the addresses) and need no alignment.
fn mem() -> MemFlagsData {
    MemFlagsData::new().with_notrap()
}

/// Little-endian lane reinterpretation.
fn le() -> MemFlagsData {
    MemFlagsData::new().with_endianness(cranelift_codegen::ir::Endianness::Little)
}

/// A blend factor, with the two constant ones kept symbolic so they cost nothing.
#[derive(Clone, Copy)]
enum Factor {
    Zero,
    One,
    Value(Value),
}

/// Per-span values, made once a span before its group loop.
#[derive(Clone, Copy)]
struct SpanValues {
    /// The `SpanCall` pointer.
    call: Value,
    /// The uniforms pointer.
    u: Value,
    span: Value,
    color: Value,
    depth: Value,
    stencil: Value,
    live: Value,
    /// The planes pointer, the row splatted and the pixel x of the span's
    /// first four lanes, for keys with a shading stage.
    planes: Option<(Value, Value, Value)>,
    /// Whether the span's primitive's 1/w plane is exactly 1 at every pixel
    /// (`a0 == 1`, `dadx == dady == 0`: every `glOrtho` draw), for keys that
    /// divide colours by it ([`Gen::perspective`]).
    w_one: Option<Value>,
    /// Whether the code runs only where `w_one` holds (the loop over a
    /// span's full groups, [`Gen::full_groups`]): no test, no second arm.
    w_is_one: bool,
    /// The span's `SpanPlanes::ones`, for keys with a smooth colour.
    ones: Option<Value>,
    /// Whether the code runs only where the primary colour's planes are
    /// bounded (`Planes::colour_bounded`): the unorm8 conversion then needs
    /// no clamp to 255 ([`Gen::full_groups`]).
    colour_bounded: bool,
    /// For each natively sampled unit of such a key: whether w and the
    /// unit's q/w plane are both exactly 1 over the span (the unit's s and t
    /// are then its planes' values).
    tex_one: [Option<Value>; crate::texture::MAX_UNITS],
}

/// The fragment values of one group of four, as the stages update them.
struct Group {
    /// The lane mask of the live lanes, once a stage has needed it (made
    /// from `bits` by [`Gen::live`]): a key without tests never makes it in
    /// a group whose four lanes are all live.
    live: Option<Value>,
    /// The group's four bits of the span's live lanes (an `i32`, not zero).
    bits: Value,
    rgba: [Value; 4],
    packed: Option<Value>,
    /// The stored color, packed, once loaded.
    dst: Option<Value>,
    /// The stencil values of the group, once loaded, and whether they changed.
    stencil: Option<(Value, bool)>,
    color_p: Value,
    depth_p: Value,
    stencil_p: Value,
    /// The group's first lane, in the pointer type.
    lane0: Value,
    /// Depth values computed by the shading stage; else read from the span.
    z: Option<Value>,
    /// The pixel x of the lanes as f32 (keys with a shading stage).
    px: Option<Value>,
    /// `1 / (1/w)` at the lanes, once the shading stage has made it.
    w: Option<Value>,
    /// Whether the group's four lanes are known live (the loop over a
    /// span's full groups): `bits` is 15 and no branch asks.
    full: bool,
    /// Whether the alpha channel (`rgba[3]`) is already shaded: the alpha
    /// test reads it before the stencil and depth tests, the other channels
    /// wait for the groups that pass them.
    alpha_shaded: bool,
    /// The shaded alpha in f32 (before it became a byte), for alpha to
    /// coverage, once the shading stage has made it.
    alpha_f: Option<Value>,
}

struct Gen<'a> {
    key: FragmentKey,
    ptr: Type,
    b: FunctionBuilder<'a>,
    /// Splatted constants of the current group, made once each: fewer values
    /// for the register allocator, which is most of the compile time.
    consts: Vec<(i64, Value)>,
    /// `255 - v` of the current blend, by `v`.
    inverses: Vec<(Value, Value)>,
    /// Whether the target is x86-64 (whose own instructions some stages use).
    x86: bool,
    /// Whether units [`native_unit`] takes are sampled in the generated code
    /// (else through the callout).
    native_sampling: bool,
    /// Splatted f32 constants of the current group, by their bits.
    fconsts: Vec<(u32, Value)>,
    /// The stack slot of the texture callout's arguments, once made.
    tex_slot: Option<cranelift_codegen::ir::StackSlot>,
    /// The native sampler's slot for gather offsets, once made.
    gather_slot: Option<cranelift_codegen::ir::StackSlot>,
    /// The mask of the pixel interleave's `pshufb`, made before the loop
    /// over full groups and kept in a register across it (x86-64).
    pshufb_mask: Option<Value>,
    /// Whether a stage after the current one (or the stencil's depth
    /// ops) reads the lanes that pass it: set before each stage.
    tail_stages: bool,
    /// A plane's coefficients `[a0, dadx, dady]` kept in registers (the
    /// depth plane across the loop over full groups of depth-only keys).
    plane_cache: Option<(usize, [Value; 3])>,
    /// The constants made once a span and kept for its groups (f32 by
    /// bits, i32 splats by value), put back by [`Self::seed`].
    seeds: Seeds,
}

/// [`Gen::seeds`]: f32 splats by their bits, i32 splats by value.
type Seeds = (Vec<(u32, Value)>, Vec<(i64, Value)>);

impl<'a> Gen<'a> {
    fn new(key: &FragmentKey, ptr: Type, b: FunctionBuilder<'a>) -> Gen<'a> {
        Gen {
            key: *key,
            ptr,
            b,
            consts: Vec::new(),
            inverses: Vec::new(),
            x86: false,
            native_sampling: true,
            fconsts: Vec::new(),
            tex_slot: None,
            gather_slot: None,
            pshufb_mask: None,
            tail_stages: true,
            plane_cache: None,
            seeds: (Vec::new(), Vec::new()),
        }
    }

    fn emit(&mut self) {
        let entry = self.b.create_block();
        self.b.append_block_params_for_function_params(entry);
        self.b.switch_to_block(entry);
        let call = self.b.block_params(entry)[0];
        let u = self.b.block_params(entry)[1];
        let ptr = self.ptr;
        let i32_at = |g: &mut Self, off: usize| g.b.ins().load(types::I32, mem(), call, off as i32);

        // The batch's spans in order: `span_head` takes span `i`, `next_span`
        // goes on to `i + 1`, `stop` returns with `i` in `SpanCall::next`.
        // The target's geometry is loaded in each span's own block (no value
        // lives across the group loop but the span's: loads that hit L1).
        let first = i32_at(self, offset_of!(SpanCall, next));
        let span_head = self.b.create_block();
        let i = self.b.append_block_param(span_head, types::I32);
        let stop = self.b.create_block();
        let stop_at = self.b.append_block_param(stop, types::I32);
        let next_span = self.b.create_block();
        self.b.ins().jump(span_head, &[first.into()]);

        self.b.switch_to_block(stop);
        self.b
            .ins()
            .store(mem(), stop_at, call, offset_of!(SpanCall, next) as i32);
        self.b.ins().return_(&[]);

        self.b.switch_to_block(next_span);
        let i1 = self.b.ins().iadd_imm_u(i, 1);
        self.b.ins().jump(span_head, &[i1.into()]);

        self.b.switch_to_block(span_head);
        let count = i32_at(self, offset_of!(SpanCall, count));
        let more = self.b.ins().icmp(IntCC::UnsignedLessThan, i, count);
        let run = self.b.create_block();
        self.b.ins().brif(more, run, &[], stop, &[i.into()]);
        self.b.switch_to_block(run);
        let spans = self.b.ins().load(ptr, mem(), call, offset_of!(SpanCall, spans) as i32);
        let i_p = self.b.ins().uextend(ptr, i);
        let off = self.b.ins().imul_imm_u(i_p, size_of::<FragmentSpan>() as i64);
        let span = self.b.ins().iadd(spans, off);
        let span_i32 = |g: &mut Self, off: usize| g.b.ins().load(types::I32, mem(), span, off as i32);
        let x0 = span_i32(self, offset_of!(FragmentSpan, x));
        let y = span_i32(self, offset_of!(FragmentSpan, y));
        // The view's rows and columns (`Target::owned_mask`).
        let y0 = i32_at(self, offset_of!(SpanCall, y0));
        let rows = i32_at(self, offset_of!(SpanCall, rows));
        let width = i32_at(self, offset_of!(SpanCall, width));
        let r = self.b.ins().isub(y, y0);
        let in_rows = self.b.ins().icmp(IntCC::UnsignedLessThan, r, rows);
        let in_cols = self.b.ins().icmp(IntCC::UnsignedLessThan, x0, width);
        let owned = self.b.ins().band(in_rows, in_cols);
        let go = self.b.create_block();
        self.b.ins().brif(owned, go, &[], next_span, &[]);
        self.b.switch_to_block(go);
        // The live lanes: the first `min(len, inside)` slots of the mask.
        let right = self.b.ins().isub(width, x0);
        let max = self.b.ins().iconst(types::I32, SPAN_MAX as i64);
        let inside = self.b.ins().umin(right, max);
        let len = span_i32(self, offset_of!(FragmentSpan, len));
        let n = self.b.ins().umin(len, inside);
        let mask = self
            .b
            .ins()
            .load(types::I64, mem(), span, offset_of!(FragmentSpan, mask) as i32);
        let n64 = self.b.ins().uextend(types::I64, n);
        let one = self.b.ins().iconst(types::I64, 1);
        let bit = self.b.ins().ishl(one, n64);
        let below = self.b.ins().iadd_imm_u(bit, -1);
        let every = self.b.ins().icmp_imm_u(IntCC::UnsignedGreaterThanOrEqual, n64, 64);
        let all = self.b.ins().iconst(types::I64, -1);
        let below = self.b.ins().select(every, all, below);
        let live = self.b.ins().band(mask, below);
        // Groups addressable from lane 0: a span whose last live group
        // crosses the right edge stops the batch (the caller runs it on a copy).
        let lz = self.b.ins().clz(live);
        let k67 = self.b.ins().iconst(types::I64, 64 + 3);
        let top = self.b.ins().isub(k67, lz);
        let lanes = self.b.ins().band_imm_u(top, !3);
        let lanes = self.b.ins().ireduce(types::I32, lanes);
        let fits = self.b.ins().icmp(IntCC::UnsignedLessThanOrEqual, lanes, inside);
        let any = self.b.ins().icmp_imm_u(IntCC::NotEqual, live, 0);
        let placed = self.b.create_block();
        let check = self.b.create_block();
        self.b.ins().brif(any, check, &[], next_span, &[]);
        self.b.switch_to_block(check);
        self.b.ins().brif(fits, placed, &[], stop, &[i.into()]);
        self.b.switch_to_block(placed);
        // The span's pixels (`Target::color_offset`, `Target::index`):
        // colour row `r` (the stride's sign flips it when top-down), depth
        // and stencil index `r · width + x`.
        // Keys that neither read nor write colour (the depth-only passes)
        // load no colour pointer (two loads a span).
        let colour = self.key.stages().as_slice().iter().any(|s| {
            matches!(
                s,
                Stage::Blend(_) | Stage::Pack { .. } | Stage::LogicOp(_) | Stage::ColorWrite(_)
            )
        });
        let color = if colour || self.key.color_format.is_deep() {
            let row_c = self.b.ins().uextend(ptr, r);
            let stride = self.b.ins().load(ptr, mem(), call, offset_of!(SpanCall, stride) as i32);
            let color_row = self.b.ins().imul(row_c, stride);
            let x_p = self.b.ins().uextend(ptr, x0);
            let bpp = self.key.color_format.bytes_per_pixel() as i64;
            let x_bytes = self.scale(x_p, bpp);
            let color_base = self.b.ins().load(ptr, mem(), call, offset_of!(SpanCall, color) as i32);
            let color = self.b.ins().iadd(color_base, color_row);
            self.b.ins().iadd(color, x_bytes)
        } else {
            self.b.ins().iconst(ptr, 0)
        };
        let index = self.b.ins().imul(r, width);
        let index = self.b.ins().iadd(index, x0);
        let index = self.b.ins().uextend(ptr, index);
        // Only the buffers the stages read (the loads are not removed when unused).
        let depth = match self.key.depth_format.filter(|_| self.key.depth.is_some()) {
            Some(f) => {
                let base = self.b.ins().load(ptr, mem(), call, offset_of!(SpanCall, depth) as i32);
                let dbytes = if f == DepthFormat::D16 { 2 } else { 4 };
                let off = self.scale(index, dbytes);
                self.b.ins().iadd(base, off)
            }
            None => self.b.ins().iconst(ptr, 0),
        };
        let stencil = if self.key.stencil_buffer && self.key.stencil.is_some() {
            let base = self
                .b
                .ins()
                .load(ptr, mem(), call, offset_of!(SpanCall, stencil) as i32);
            self.b.ins().iadd(base, index)
        } else {
            self.b.ins().iconst(ptr, 0)
        };
        let sv = SpanValues {
            call,
            u,
            span,
            color,
            depth,
            stencil,
            live,
            planes: None,
            w_one: None,
            w_is_one: false,
            ones: None,
            colour_bounded: false,
            tex_one: [None; crate::texture::MAX_UNITS],
        };
        let mut sv = sv;
        // A shading stage that makes nothing from the planes (the
        // stencil-only passes' keys) loads none and carries no pixel x.
        let shades = self.key.shade.filter(|s| s.color || s.depth || s.textured());
        if let Some(shade) = shades {
            // The span's entry of `SpanCall::planes`.
            let table = self.b.ins().load(ptr, mem(), call, offset_of!(SpanCall, planes) as i32);
            let off = self.b.ins().imul_imm_u(i_p, size_of::<SpanPlanes>() as i64);
            let entry = self.b.ins().iadd(table, off);
            let height = i32_at(self, offset_of!(SpanCall, height));
            let (planes, row, px0) = self.planes_and_row(entry, (x0, y, height));
            sv.planes = Some((planes, row, px0));
            if shade.color && !shade.flat {
                // The caller found which planes are exactly 1 (`SpanPlanes::ones`).
                let ones = self
                    .b
                    .ins()
                    .load(types::I32, mem(), entry, offset_of!(SpanPlanes, ones) as i32);
                sv.w_one = Some(self.b.ins().band_imm_u(ones, 1));
                sv.ones = Some(ones);
                for (u, unit) in shade.tex.iter().enumerate() {
                    if unit.as_ref().is_some_and(|t| self.native_sampling && native_unit(t)) {
                        sv.tex_one[u] = Some(self.b.ins().band_imm_u(ones, 2 << u));
                    }
                }
            }
        }
        let exit = next_span;

        // The scissor's rows are tested once per span.
        if self.key.scissor {
            let sy0 = self.uniform_i32(u, uniform_offset(offset_of!(FragmentUniforms, scissor) + 4));
            let sy1 = self.uniform_i32(u, uniform_offset(offset_of!(FragmentUniforms, scissor) + 12));
            let lo = self.b.ins().icmp(IntCC::SignedGreaterThanOrEqual, y, sy0);
            let hi = self.b.ins().icmp(IntCC::SignedLessThan, y, sy1);
            let inside = self.b.ins().band(lo, hi);
            let go = self.b.create_block();
            self.b.ins().brif(inside, go, &[], exit, &[]);
            self.b.switch_to_block(go);
            // And its columns: the lanes outside them leave the live bits
            // here (the scissor test comes first and a fragment it kills
            // changes nothing), so no group tests them (the `ops` frame's
            // groups: 13 instructions fewer).
            let columns = self.scissor_columns(u, x0);
            sv.live = self.b.ins().band(sv.live, columns);
        }

        // Groups of four from lane 0 while live lanes remain (the last live
        // lane is in group `groups - 1`), carrying the first lane, the live
        // bits from it on and, for keys with a shading stage, the pixel x of
        // the group's lanes as f32 (exact: below 2^24).
        let head = self.b.create_block();
        // The first lane in the pointer type: no extension a group.
        let lane0 = self.b.append_block_param(head, self.ptr);
        let rest = self.b.append_block_param(head, types::I64);
        let zero = self.b.ins().iconst(self.ptr, 0);
        let px = sv.planes.map(|(_, _, px0)| {
            let four = self.b.ins().f32const(4.0);
            (px0, self.b.ins().splat(types::F32X4, four))
        });
        let px_head = px.map(|_| self.b.append_block_param(head, types::F32X4));
        let mut args = vec![zero.into(), sv.live.into()];
        if let Some((px0, _)) = px {
            args.push(px0.into());
        }
        // A key without texture units (no callout, whose values would be
        // spilled across it) keeps the unorm8 conversion's 255.0 in a
        // register for the span: one instruction fewer a group of the
        // `fill` frame's 50.
        self.consts.clear();
        self.fconsts.clear();
        let seeded = self
            .key
            .shade
            .filter(|s| !s.textured())
            .map(|_| (255.0f32.to_bits(), self.fconst(255.0)));
        self.seeds = (seeded.into_iter().collect(), Vec::new());
        // Keys that shade depth alone (the shadow maps' depth-only pass,
        // the light passes' per-sample half) keep the depth plane's
        // coefficients, the conversion's bound and zero in registers for
        // the span: 5 instructions fewer a group.
        let depth_only = self
            .key
            .shade
            .filter(|s| s.depth && !s.color && !s.textured())
            .and(self.key.depth_format);
        if let (Some(format), Some((planes, _, _))) = (depth_only, sv.planes) {
            let coeffs = [0, 1, 2].map(|c| self.plane_coeff(planes, crate::shade::slot::Z, c));
            self.plane_cache = Some((crate::shade::slot::Z, coeffs));
            if matches!(format, DepthFormat::D16 | DepthFormat::D24) {
                let m = format.max_value() as f32;
                let m = (m.to_bits(), self.fconst(m));
                let zero = (0, self.splat(0));
                self.seeds.0.push(m);
                self.seeds.1.push(zero);
            }
        }
        if self.full_loop() {
            self.full_groups(&sv, px, (&args, head, exit));
        } else {
            self.b.ins().jump(head, &args);
        }
        // A group with live lanes goes straight to work; only one without
        // asks whether any live lane is left (two instructions fewer a group
        // than asking first).
        self.b.switch_to_block(head);
        let next = self.b.create_block();
        let bits = self.b.ins().ireduce(types::I32, rest);
        let bits = self.b.ins().band_imm_u(bits, 15);
        let work = self.b.create_block();
        let empty = self.b.create_block();
        self.b.ins().brif(bits, work, &[], empty, &[]);
        self.b.switch_to_block(empty);
        self.b.ins().brif(rest, next, &[], exit, &[]);

        self.b.switch_to_block(work);
        // Uniforms are loaded in each group rather than once per span: keeping a
        // dozen splats live across the loop costs more register-allocation time
        // than the loads (which hit L1) cost at run time.
        self.seed();
        let uniforms = Uniforms::load(self, u, call);
        let mut group = self.group(&sv, lane0, bits);
        group.px = px_head;
        self.stages(group, &sv, &uniforms, next);

        self.b.switch_to_block(next);
        let lane4 = self.b.ins().iadd_imm_u(lane0, 4);
        let rest4 = self.b.ins().ushr_imm_u(rest, 4);
        let mut args = vec![lane4.into(), rest4.into()];
        if let (Some(p), Some((_, four))) = (px_head, px) {
            args.push(self.b.ins().fadd(p, four).into());
        }
        self.b.ins().jump(head, &args);
    }

    /// Whether the key's spans run their leading full groups in a loop of
    /// their own ([`Self::full_groups`]): keys whose stages test no lane
    /// but depth (their groups start with four live lanes) and sample no
    /// texture (whose bodies are large: a second copy would cost compile
    /// time).
    fn full_loop(&self) -> bool {
        Self::full_loop_of(&self.key)
    }

    /// [`Self::full_loop`] of `k`.
    fn full_loop_of(k: &FragmentKey) -> bool {
        // The depth test is allowed: a full group's pass mask is its
        // compare, with no live mask to load and apply (the shadow maps'
        // depth-only key).
        // So is a stencil test that always passes (its ops only write).
        let stencil_kills = k.stencil.is_some_and(|s| s.func != CompareFunc::Always) && k.stencil_buffer;
        let tests = k.alpha_test.is_some() || stencil_kills;
        // The deep formats' groups take `deep_stages`, which has no such loop.
        !tests && !k.shade.is_some_and(|s| s.textured()) && !k.color_format.is_deep()
    }

    /// [`reads_colour_bound`] of the key.
    fn bounded_colour(&self) -> bool {
        reads_colour_bound(&self.key)
    }

    /// Ends the span's block with the loop over its leading pairs of full
    /// groups (where the 1/w plane is exactly 1, for keys that divide by
    /// it, and the colour bounded, for keys that read the bound), then
    /// hands the rest of its live lanes to the general loop at `head`
    /// (whose arguments from lane 0 are `args`), or goes to `exit`.
    /// `px` is the pixel x of lane 0
    /// and the step of four (keys with a shading stage).
    ///
    /// The loop's groups know their four lanes live and their w one: no
    /// live bits to shift and test, no test of w, the store with no choice;
    /// two groups a turn, the second's pixels at constant offsets from the
    /// first's, one compare of the lane with the last pair's.
    fn full_groups(
        &mut self,
        sv: &SpanValues,
        px: Option<(Value, Value)>,
        (args, head, exit): (&[BlockArg], Block, Block),
    ) {
        let ptr = self.ptr;
        // The lanes of the pairs of full groups from lane 0: the trailing
        // live bits (64 when all are) rounded down to eights.
        let dead = self.b.ins().bnot(sv.live);
        let ones = self.b.ins().ctz(dead);
        let end = self.b.ins().band_imm_u(ones, !7);
        // Where the key asks, only spans whose 1/w plane is exactly 1 (and
        // whose colour is bounded, for keys that then skip the clamp).
        let bounded = self.bounded_colour();
        let end = match sv.ones {
            Some(ones) => {
                let need = i64::from(if bounded { 1 | COLOUR_BOUNDED } else { 1 });
                let has = self.b.ins().band_imm_u(ones, need);
                let ok = self.b.ins().icmp_imm_u(IntCC::Equal, has, need);
                let none = self.b.ins().iconst(types::I64, 0);
                self.b.ins().select(ok, end, none)
            }
            None => end,
        };
        let end = if ptr == types::I64 {
            end
        } else {
            self.b.ins().ireduce(ptr, end)
        };
        let body = self.b.create_block();
        let lane0 = self.b.append_block_param(body, ptr);
        let px_body = px.map(|_| self.b.append_block_param(body, types::F32X4));
        let after = self.b.create_block();
        let lane_after = self.b.append_block_param(after, ptr);
        let px_after = px.map(|_| self.b.append_block_param(after, types::F32X4));
        let mut first = vec![args[0]];
        first.extend(args.get(2).copied());
        self.pshufb_mask = self.make_pshufb_mask();
        self.b.ins().brif(end, body, &first, head, args);

        self.b.switch_to_block(body);
        self.seed();
        let uniforms = Uniforms::load(self, sv.u, sv.call);
        // The loop runs only where w is one, for keys that ask.
        let fast = SpanValues {
            w_is_one: sv.w_one.is_some(),
            colour_bounded: bounded && sv.ones.is_some(),
            ..*sv
        };
        // Two groups a turn: the loop's lane, compare and branch once for
        // both.
        let mut px_group = px_body;
        for half in 0..2 {
            let bits = self.b.ins().iconst(types::I32, 15);
            let mut group = self.group(&fast, lane0, bits);
            if half == 1 {
                self.seed();
                // The second group's pixels at constant offsets from the
                // first's (folded into the addresses: no add a turn).
                let bpp = self.key.color_format.bytes_per_pixel() as i64;
                let dbytes = match self.key.depth_format {
                    Some(DepthFormat::D16) => 2,
                    _ => 4,
                };
                group.color_p = self.b.ins().iadd_imm_u(group.color_p, 4 * bpp);
                group.depth_p = self.b.ins().iadd_imm_u(group.depth_p, 4 * dbytes);
                group.stencil_p = self.b.ins().iadd_imm_u(group.stencil_p, 4);
                group.lane0 = self.b.ins().iadd_imm_u(lane0, 4);
            }
            group.px = px_group;
            group.full = true;
            let next = self.b.create_block();
            self.stages(group, &fast, &uniforms, next);
            self.b.switch_to_block(next);
            if let (Some(p), Some((_, four))) = (px_group, px) {
                px_group = Some(self.b.ins().fadd(p, four));
            }
        }
        self.pshufb_mask = None;

        let lane8 = self.b.ins().iadd_imm_u(lane0, 8);
        let mut again: Vec<BlockArg> = vec![lane8.into()];
        again.extend(px_group.map(BlockArg::from));
        let more = self.b.ins().icmp(IntCC::UnsignedLessThan, lane8, end);
        self.b.ins().brif(more, body, &again, after, &again);

        // The rest of the span's lanes from `end` on, if any.
        self.b.switch_to_block(after);
        let done = self.b.ins().icmp_imm_u(IntCC::Equal, lane_after, 64);
        let rest_block = self.b.create_block();
        self.b.ins().brif(done, exit, &[], rest_block, &[]);
        self.b.switch_to_block(rest_block);
        let shift = if ptr == types::I64 {
            lane_after
        } else {
            self.b.ins().uextend(types::I64, lane_after)
        };
        let rest = self.b.ins().ushr(sv.live, shift);
        let mut to_head: Vec<BlockArg> = vec![lane_after.into(), rest.into()];
        to_head.extend(px_after.map(BlockArg::from));
        self.b.ins().jump(head, &to_head);
    }

    /// Starts a group's constants from the span's [`Self::seeds`].
    fn seed(&mut self) {
        self.consts.clear();
        self.consts.extend(self.seeds.1.iter().copied());
        self.fconsts.clear();
        self.fconsts.extend(self.seeds.0.iter().copied());
    }

    /// The bits of the span's lanes inside the scissor box's columns
    /// `x0 <= x < x1` (as `i32`s, the compare the interpreter makes), in
    /// `i64` so that no difference overflows.
    fn scissor_columns(&mut self, u: Value, span_x: Value) -> Value {
        let x = self.b.ins().uextend(types::I64, span_x);
        let zero = self.b.ins().iconst(types::I64, 0);
        let all = self.b.ins().iconst(types::I64, 64);
        let lanes_below = |g: &mut Self, off: usize| {
            let bound = g.uniform_i32(u, uniform_offset(offset_of!(FragmentUniforms, scissor) + off));
            let bound = g.b.ins().sextend(types::I64, bound);
            let n = g.b.ins().isub(bound, x);
            let n = g.b.ins().smax(n, zero);
            let n = g.b.ins().smin(n, all);
            // The bits of lanes `0..n`: `(1 << n) - 1`, all of them for 64.
            let one = g.b.ins().iconst(types::I64, 1);
            let bit = g.b.ins().ishl(one, n);
            let below = g.b.ins().iadd_imm_u(bit, -1);
            let every = g.b.ins().icmp_imm_u(IntCC::Equal, n, 64);
            let ones = g.b.ins().iconst(types::I64, -1);
            g.b.ins().select(every, ones, below)
        };
        let left = lanes_below(self, 0);
        let right = lanes_below(self, 8);
        self.b.ins().band_not(right, left)
    }

    fn uniform_i32(&mut self, u: Value, off: usize) -> Value {
        self.b.ins().load(types::I32, mem(), u, off as i32)
    }

    fn splat(&mut self, v: i64) -> Value {
        if v == 0 && self.key.shade.is_some_and(|s| s.textured()) {
            // In textured keys zero is one `pxor` where it is used: kept for
            // the group, it lived across the texture stage and was spilled
            // (the `tex` frame's depth-tested groups stored and reloaded
            // it): 1277.7 -> 1268.8 M instructions a frame. (Untextured
            // keys keep it: the `ops` frame took 0.8% more without.)
            return self.vconst([0; 4]);
        }
        if let Some(&(_, c)) = self.consts.iter().find(|(k, _)| *k == v) {
            return c;
        }
        // A constant-pool vector: one load (or the operand of its user)
        // where `iconst` and `splat` take three instructions.
        let c = self.vconst([v as u32; 4]);
        self.consts.push((v, c));
        c
    }

    fn vconst(&mut self, lanes: [u32; 4]) -> Value {
        let mut bytes = [0u8; 16];
        for (i, l) in lanes.iter().enumerate() {
            bytes[i * 4..i * 4 + 4].copy_from_slice(&l.to_le_bytes());
        }
        let c = self.b.func.dfg.constants.insert(V128Imm(bytes).to_vec().into());
        self.b.ins().vconst(I32X4, c)
    }

    fn vconst_bytes(&mut self, bytes: [u8; 16]) -> Value {
        let c = self.b.func.dfg.constants.insert(bytes.to_vec().into());
        self.b.ins().vconst(types::I8X16, c)
    }

    /// `v * n`, a shift when `n` is a power of two.
    fn scale(&mut self, v: Value, n: i64) -> Value {
        if n > 0 && (n as u64).is_power_of_two() {
            self.b.ins().ishl_imm_u(v, i64::from((n as u64).trailing_zeros()))
        } else {
            self.b.ins().imul_imm_u(v, n)
        }
    }

    /// The lane mask of group `g` and its span data.
    fn group(&mut self, sv: &SpanValues, lane0: Value, bits: Value) -> Group {
        let zero = self.splat(0);
        let lane0_p = lane0;
        let bpp = self.key.color_format.bytes_per_pixel() as i64;
        let off = self.scale(lane0_p, bpp);
        let color_p = self.b.ins().iadd(sv.color, off);
        let dbytes = match self.key.depth_format {
            Some(DepthFormat::D16) => 2,
            _ => 4,
        };
        let off = if dbytes == bpp {
            off
        } else {
            self.scale(lane0_p, dbytes)
        };
        let depth_p = self.b.ins().iadd(sv.depth, off);
        let stencil_p = self.b.ins().iadd(sv.stencil, lane0_p);
        Group {
            live: None,
            bits,
            rgba: [zero; 4],
            packed: None,
            dst: None,
            stencil: None,
            color_p,
            depth_p,
            stencil_p,
            lane0,
            z: None,
            px: None,
            w: None,
            full: false,
            alpha_shaded: false,
            alpha_f: None,
        }
    }

    /// The lane mask of the group's live lanes, made from its bits the
    /// first time a stage asks.
    fn live(&mut self, g: &mut Group) -> Value {
        if let Some(l) = g.live {
            return l;
        }
        if g.full {
            let all = self.splat(-1);
            g.live = Some(all);
            return all;
        }
        // One load from the table of the 16 masks (3 instructions where
        // splatting and comparing the bits take 5).
        let table = self.b.ins().iconst(self.ptr, LIVE_MASKS.0.as_ptr() as i64);
        let bits_p = self.b.ins().uextend(self.ptr, g.bits);
        let off = self.b.ins().ishl_imm_u(bits_p, 4);
        let p = self.b.ins().iadd(table, off);
        let live = self.b.ins().load(I32X4, mem(), p, 0);
        g.live = Some(live);
        live
    }

    /// The group's fragments' colours from the span packed as a byte
    /// format stores them (as [`Self::pack`] packs the four
    /// [`Self::span_channel`]s): each channel's four bytes one 32-bit
    /// load into its lane, the lanes interleaved by one shuffle. 5
    /// instructions where the channels and the pack take 14.
    fn span_packed(&mut self, sv: &SpanValues, lane0: Value) -> Value {
        let fields = [
            offset_of!(FragmentSpan, r),
            offset_of!(FragmentSpan, g),
            offset_of!(FragmentSpan, b),
            offset_of!(FragmentSpan, a),
        ];
        let p = self.b.ins().iadd(sv.span, lane0);
        let r = self.b.ins().load(types::I32, mem(), p, fields[0] as i32);
        let mut v = self.b.ins().scalar_to_vector(I32X4, r);
        for (c, &field) in fields.iter().enumerate().skip(1) {
            let x = self.b.ins().load(types::I32, mem(), p, field as i32);
            v = self.b.ins().insertlane(v, x, c as u8);
        }
        let planar = self.b.ins().bitcast(types::I8X16, le(), v);
        self.interleave(planar)
    }

    /// The blend `ONE, ONE` with `FUNC_ADD` of packed byte pixels:
    /// `min(s + d, 255)` in each byte, as [`Self::blend16`] gives it.
    fn add_saturated(&mut self, src: Value, dst: Value) -> Value {
        let s = self.b.ins().bitcast(types::I8X16, le(), src);
        let d = self.b.ins().bitcast(types::I8X16, le(), dst);
        let sum = self.b.ins().uadd_sat(s, d);
        self.b.ins().bitcast(I32X4, le(), sum)
    }

    /// Channel `c` (0 = red .. 3 = alpha) of the group's fragments.
    fn span_channel(&mut self, sv: &SpanValues, lane0: Value, c: usize) -> Value {
        let field = [
            offset_of!(FragmentSpan, r),
            offset_of!(FragmentSpan, g),
            offset_of!(FragmentSpan, b),
            offset_of!(FragmentSpan, a),
        ][c];
        let p = self.b.ins().iadd(sv.span, lane0);
        let x = self.b.ins().uload8x8(mem(), p, field as i32);
        self.b.ins().uwiden_low(x)
    }

    fn stages(&mut self, mut g: Group, sv: &SpanValues, u: &Uniforms, next: Block) {
        if self.key.color_format.is_deep() {
            return self.deep_stages(g, sv, u, next);
        }
        let stages = self.key.stages();
        let needs_color = stages
            .as_slice()
            .iter()
            .any(|s| matches!(s, Stage::Pack { .. } | Stage::Blend(_)));
        let coverage = self.key.shade.map(|s| s.coverage).filter(AlphaCoverage::is_on);
        let needs_alpha = needs_color || self.key.alpha_test.is_some() || coverage.is_some();
        if let Some(shade) = self.key.shade.filter(|s| s.depth) {
            self.shade_depth(&mut g, sv, &shade);
        }
        // The colour from the planes is made just before the first stage that
        // reads it, so that groups the scissor, stencil or depth test kill
        // skip it (the 20k-triangle frame's depth test kills most).
        let mut colour_due = self.key.shade.filter(|s| s.color);
        let from_span = colour_due.is_none();
        // The span's colour is read just before the first stage that needs
        // it (groups the tests kill skip it); where that stage is the
        // blend `ONE, ONE` or the pack of a byte format, as the four
        // channels' bytes side by side, interleaved by one `pshufb`
        // ([`Self::span_packed`]).
        let mut span_due = needs_alpha && from_span;
        let list = stages.as_slice();
        for (at, stage) in list.iter().enumerate() {
            self.tail_stages = at + 1 < list.len() || (self.key.stencil.is_some() && self.key.stencil_buffer);
            if span_due
                && matches!(
                    stage,
                    Stage::AlphaTest(_) | Stage::AlphaCoverage(_) | Stage::Blend(_) | Stage::Pack { .. }
                )
            {
                span_due = false;
                let bytes = matches!(
                    self.key.color_format,
                    ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8
                );
                match *stage {
                    Stage::Blend(b) if bytes && self.key.color_format != ColorFormat::Rgb8 && is_add_ones(&b) => {
                        let src = self.span_packed(sv, g.lane0);
                        let dst = self.load_dst(&mut g);
                        g.packed = Some(self.add_saturated(src, dst));
                        continue;
                    }
                    Stage::Pack { .. } if bytes => {
                        g.packed = Some(self.span_packed(sv, g.lane0));
                    }
                    _ => {
                        if needs_color {
                            for c in 0..3 {
                                g.rgba[c] = self.span_channel(sv, g.lane0, c);
                            }
                        }
                        g.rgba[3] = self.span_channel(sv, g.lane0, 3);
                    }
                }
            }
            match (colour_due, stage) {
                // Untextured alpha depends on the alpha plane alone: the
                // alpha test gets it now, the other channels are shaded only
                // for the groups the stencil and depth tests leave (the `ops`
                // frame's depth test kills most).
                (Some(shade), Stage::AlphaTest(_) | Stage::AlphaCoverage(_)) if !shade.textured() => {
                    self.shade_alpha(&mut g, sv, &shade)
                }
                (Some(shade), Stage::AlphaTest(_) | Stage::AlphaCoverage(_) | Stage::Blend(_) | Stage::Pack { .. }) => {
                    self.shade_color(&mut g, sv, &shade);
                    colour_due = None;
                }
                _ => {}
            }
            match *stage {
                Stage::Shade(_) => {}
                // Tested once a span (`emit`).
                Stage::Scissor => {}
                Stage::AlphaTest(func) => {
                    // Alpha and the reference are bytes: signed compares
                    // (one instruction on x86-64) order them as unsigned.
                    let pass = self.compare_as(func, g.rgba[3], u.alpha_ref, true);
                    let live = self.live(&mut g);
                    g.live = Some(self.b.ins().band(live, pass));
                    self.skip_if_dead(&g, next);
                }
                Stage::AlphaCoverage(c) => {
                    if let Some(q) = c.quarters {
                        // The span's colour: its byte times 1/255, as the interpreter.
                        let a = match g.alpha_f {
                            Some(a) => a,
                            None => {
                                let f = self.b.ins().fcvt_from_sint(types::F32X4, g.rgba[3]);
                                let k = self.fconst(1.0 / 255.0);
                                self.b.ins().fmul(f, k)
                            }
                        };
                        let t = self.fconst(AlphaCoverage::threshold(q));
                        // Ordered: NaN fails, as `!(a > t)` in the interpreter.
                        let pass = self.b.ins().fcmp(FloatCC::GreaterThan, a, t);
                        let live = self.live(&mut g);
                        g.live = Some(self.b.ins().band(live, pass));
                        self.skip_if_dead(&g, next);
                    }
                    if c.to_one {
                        g.rgba[3] = self.splat(255);
                        g.alpha_shaded = true;
                    }
                }
                Stage::StencilTest { stencil, depth_on } => self.stencil_test(&mut g, (stencil, depth_on), u, next),
                Stage::DepthTest { depth, stencil } => self.depth_test(&mut g, sv, (depth, stencil), u, next),
                Stage::Count => self.count(&mut g, sv),
                Stage::Blend(blend) => {
                    let dst = self.load_dst(&mut g);
                    let bytes = matches!(self.key.color_format, ColorFormat::Rgba8 | ColorFormat::Bgra8);
                    if bytes && is_add_ones(&blend) {
                        // `min(s + d, 255)` a channel: the source packed,
                        // one saturating byte add (`paddusb`).
                        let src = self.pack(g.rgba, None);
                        g.packed = Some(self.add_saturated(src, dst));
                    } else if blend.eq_rgb == blend.eq_alpha {
                        self.blend16(&blend, &mut g, dst, u);
                    } else {
                        let d = self.unpack(dst);
                        g.rgba = self.blend(&blend, g.rgba, d, u);
                    }
                }
                Stage::Pack { dither } => {
                    // The shading stage may have packed the colour already.
                    if g.packed.is_none() {
                        g.packed = Some(self.pack(g.rgba, dither.then_some(u.dither)));
                    }
                }
                Stage::LogicOp(op) => {
                    let dst = self.load_dst(&mut g);
                    let s = g.packed.expect("Pack precedes LogicOp in every stage list");
                    g.packed = Some(self.logic_op(op, s, dst));
                }
                Stage::ColorWrite(mask) => {
                    let s = g.packed.expect("Pack precedes ColorWrite in every stage list");
                    let format = self.key.color_format;
                    let bits = pixel::mask_bits(format, mask);
                    let value = if bits == pixel::mask_bits(format, ColorMask::ALL) {
                        s
                    } else {
                        let dst = self.load_dst(&mut g);
                        let m = self.splat(i64::from(bits));
                        self.b.ins().bitselect(m, s, dst)
                    };
                    if g.live.is_none() && g.full {
                        self.store_color(g.color_p, value);
                        continue;
                    }
                    if g.live.is_none() {
                        // No test ran: a group whose four lanes are live stores
                        // its pixels without reading them (the `fill` frame's
                        // groups, nearly all full: 7 instructions fewer).
                        let full = self.b.ins().icmp_imm_u(IntCC::Equal, g.bits, 15);
                        let whole = self.b.create_block();
                        let part = self.b.create_block();
                        self.b.ins().brif(full, whole, &[], part, &[]);
                        self.b.switch_to_block(whole);
                        // Constants made in this block do not dominate `part`.
                        let (consts, fconsts) = (self.consts.len(), self.fconsts.len());
                        self.store_color(g.color_p, value);
                        self.consts.truncate(consts);
                        self.fconsts.truncate(fconsts);
                        self.b.ins().jump(next, &[]);
                        self.b.switch_to_block(part);
                    }
                    let live = self.live(&mut g);
                    let dst = self.load_dst(&mut g);
                    let out = self.select(live, value, dst);
                    self.store_color(g.color_p, out);
                }
            }
        }
        self.b.ins().jump(next, &[]);
    }

    /// The stencil test stage (`interp::stencil_stage`) of group `g`:
    /// its `fail` op and, with the depth test off, `zpass`; ends the group
    /// at `next` when no lane passes.
    fn stencil_test(&mut self, g: &mut Group, (stencil, depth_on): (StencilKey, bool), u: &Uniforms, next: Block) {
        if !self.key.stencil_buffer {
            return;
        }
        let s = self.load_stencil(g);
        if stencil.func == CompareFunc::Always {
            // Every live lane passes: no compare, no `fail` op,
            // no lane dies (the `ops` frame's stencil test).
            if !depth_on && stencil.zpass != StencilOp::Keep {
                let live = self.live(g);
                let s_new = self.stencil_select(stencil.zpass, live, s, u);
                g.stencil = Some((s_new, true));
                self.store_stencil(g);
            }
            return;
        }
        let masked = self.b.ins().band(s, u.stencil_value_mask);
        let pass = self.compare(stencil.func, u.stencil_ref_masked, masked);
        let live = self.live(g);
        let fail = self.b.ins().band_not(live, pass);
        let mut s_new = self.stencil_select(stencil.fail, fail, s, u);
        let passed = self.b.ins().band(live, pass);
        if !depth_on {
            s_new = self.stencil_select(stencil.zpass, passed, s_new, u);
        }
        let changed = stencil.fail != StencilOp::Keep || (!depth_on && stencil.zpass != StencilOp::Keep);
        g.stencil = Some((s_new, changed));
        self.store_stencil(g);
        g.live = Some(passed);
        self.skip_if_dead(g, next);
    }

    /// The depth test stage (`interp::depth_stage`) of group `g`: the
    /// test, the depth write and the stencil's `zfail`/`zpass` ops; ends
    /// the group at `next` when no lane passes.
    fn depth_test(
        &mut self,
        g: &mut Group,
        sv: &SpanValues,
        (depth, stencil): (DepthKey, Option<StencilKey>),
        u: &Uniforms,
        next: Block,
    ) {
        let Some(format) = self.key.depth_format else { return };
        // Depth from the planes is already at most the format's largest value.
        let z = match g.z {
            Some(z) => z,
            None => {
                let zoff = self.scale(g.lane0, 4);
                let zp = self.b.ins().iadd(sv.span, zoff);
                let z = self.b.ins().load(I32X4, mem(), zp, offset_of!(FragmentSpan, z) as i32);
                let max = self.splat(i64::from(format.max_value()));
                self.b.ins().umin(z, max)
            }
        };
        let stored = self.load_depth(format, g.depth_p);
        // 16- and 24-bit values are non-negative as i32, where x86
        // compares in one instruction (unsigned takes three).
        let signed = format != DepthFormat::D32;
        // Whether anything reads the passing lanes: a depth-only key's
        // test is its last stage and nothing asks (the shadow maps' pass).
        let tail = self.tail_stages;
        // Where no later stage reads the pass mask, a write of the
        // ordering tests is the lanes' minimum or maximum (`z < stored ?
        // z : stored` is `min(z, stored)`, equal values are the same
        // bits): one `pminsd`/`pmaxsd` for the compare, the live mask's
        // `pand` and the `blendvps` (a full group's).
        let extreme = match depth.func {
            CompareFunc::Less | CompareFunc::Lequal => Some(false),
            CompareFunc::Greater | CompareFunc::Gequal => Some(true),
            _ => None,
        }
        .filter(|_| depth.write && !tail);
        // A full group's lanes are all live: the pass mask is the compare's.
        let all_live = g.full && g.live.is_none();
        let pass = if extreme.is_none() {
            let pass = self.compare_as(depth.func, z, stored, signed);
            if all_live {
                Some(pass)
            } else {
                let live = self.live(g);
                Some(self.b.ins().band(pass, live))
            }
        } else {
            None
        };
        if depth.write {
            let out = match extreme {
                Some(max) => {
                    let m = match (max, signed) {
                        (true, true) => self.b.ins().smax(z, stored),
                        (true, false) => self.b.ins().umax(z, stored),
                        (false, true) => self.b.ins().smin(z, stored),
                        (false, false) => self.b.ins().umin(z, stored),
                    };
                    if all_live {
                        m
                    } else {
                        let live = self.live(g);
                        self.select(live, m, stored)
                    }
                }
                None => {
                    let pass = pass.expect("made for writes other than the extremes");
                    self.select(pass, z, stored)
                }
            };
            self.store_depth(format, g.depth_p, out);
        }
        let Some(pass) = pass else { return };
        let live = self.live(g);
        if let (Some(StencilKey { zfail, zpass, .. }), true) = (stencil, self.key.stencil_buffer) {
            let s = self.load_stencil(g);
            let s2 = if zfail == zpass {
                // The lanes that fail and those that pass are
                // the live ones, apart: one op over all of them.
                self.stencil_select(zpass, live, s, u)
            } else {
                let zfailed = self.b.ins().band_not(live, pass);
                let s1 = self.stencil_select(zfail, zfailed, s, u);
                self.stencil_select(zpass, pass, s1, u)
            };
            let changed = zfail != StencilOp::Keep || zpass != StencilOp::Keep;
            let was = g.stencil.is_some_and(|(_, c)| c);
            g.stencil = Some((s2, changed || was));
            self.store_stencil(g);
        }
        g.live = Some(pass);
        if tail {
            self.skip_if_dead(g, next);
        }
    }

    /// Counts the group's live lanes into `SpanCall::passed` (the `Count` stage).
    fn count(&mut self, g: &mut Group, sv: &SpanValues) {
        // The live lanes' sign bits as a 4-bit mask, counted
        // (movmskps, popcnt) and added to `SpanCall::passed`.
        let live = self.live(g);
        let bits = self.b.ins().vhigh_bits(types::I32, live);
        let n = self.b.ins().popcnt(bits);
        let n = self.b.ins().uextend(types::I64, n);
        let at = offset_of!(SpanCall, passed) as i32;
        let sum = self.b.ins().load(types::I64, mem(), sv.call, at);
        let sum = self.b.ins().iadd(sum, n);
        self.b.ins().store(mem(), sum, sv.call, at);
    }

    /// `t` in the lanes of the lane mask `mask` (each lane all ones or all
    /// zeros), `f` elsewhere: one `blendvps` on x86-64, where `bitselect`
    /// of a mask Cranelift cannot prove lane-wise (a test's `band` of two
    /// compares) takes three instructions.
    fn select(&mut self, mask: Value, t: Value, f: Value) -> Value {
        if self.x86 {
            self.b.ins().blendv(mask, t, f)
        } else {
            self.b.ins().bitselect(mask, t, f)
        }
    }

    /// Ends the group when no lane is live any more.
    fn skip_if_dead(&mut self, g: &Group, next: Block) {
        let Some(live) = g.live else { return };
        let any = self.b.ins().vany_true(live);
        let go = self.b.create_block();
        self.b.ins().brif(any, go, &[], next, &[]);
        self.b.switch_to_block(go);
    }

    /// Lanes where `incoming <func> stored` holds (unsigned), as a lane mask.
    fn compare(&mut self, func: CompareFunc, incoming: Value, stored: Value) -> Value {
        self.compare_as(func, incoming, stored, false)
    }

    /// [`Self::compare`], as signed integers when `signed` (for lanes known
    /// to be below `2^31`, where both orders agree).
    fn compare_as(&mut self, func: CompareFunc, incoming: Value, stored: Value, signed: bool) -> Value {
        let (lt, le, gt, ge) = if signed {
            (
                IntCC::SignedLessThan,
                IntCC::SignedLessThanOrEqual,
                IntCC::SignedGreaterThan,
                IntCC::SignedGreaterThanOrEqual,
            )
        } else {
            (
                IntCC::UnsignedLessThan,
                IntCC::UnsignedLessThanOrEqual,
                IntCC::UnsignedGreaterThan,
                IntCC::UnsignedGreaterThanOrEqual,
            )
        };
        let cc = match func {
            CompareFunc::Never => return self.splat(0),
            CompareFunc::Always => return self.splat(-1),
            CompareFunc::Less => lt,
            CompareFunc::Equal => IntCC::Equal,
            CompareFunc::Lequal => le,
            CompareFunc::Greater => gt,
            CompareFunc::Notequal => IntCC::NotEqual,
            CompareFunc::Gequal => ge,
        };
        self.b.ins().icmp(cc, incoming, stored)
    }

    fn load_stencil(&mut self, g: &mut Group) -> Value {
        if let Some((s, _)) = g.stencil {
            return s;
        }
        let word = self.b.ins().load(types::I32, mem(), g.stencil_p, 0);
        let v = self.b.ins().scalar_to_vector(I32X4, word);
        let bytes = self.b.ins().bitcast(types::I8X16, le(), v);
        let halves = self.b.ins().uwiden_low(bytes);
        let s = self.b.ins().uwiden_low(halves);
        g.stencil = Some((s, false));
        s
    }

    fn store_stencil(&mut self, g: &mut Group) {
        let Some((s, true)) = g.stencil else { return };
        let halves = self.b.ins().unarrow(s, s);
        let bytes = self.b.ins().unarrow(halves, halves);
        let words = self.b.ins().bitcast(I32X4, le(), bytes);
        let word = self.b.ins().extractlane(words, 0);
        self.b.ins().store(mem(), word, g.stencil_p, 0);
    }

    /// `op` applied (through the write mask) in the lanes of `mask`; `s` elsewhere.
    fn stencil_select(&mut self, op: StencilOp, mask: Value, s: Value, u: &Uniforms) -> Value {
        let new = match op {
            StencilOp::Keep => return s,
            StencilOp::Zero => self.splat(0),
            StencilOp::Replace => u.stencil_ref,
            StencilOp::Incr => {
                let one = self.splat(1);
                let max = self.splat(255);
                let v = self.b.ins().iadd(s, one);
                self.b.ins().umin(v, max)
            }
            StencilOp::Decr => {
                let one = self.splat(1);
                let zero = self.splat(0);
                let v = self.b.ins().isub(s, one);
                self.b.ins().smax(v, zero)
            }
            StencilOp::Invert => {
                let ff = self.splat(255);
                self.b.ins().bxor(s, ff)
            }
            StencilOp::IncrWrap => {
                let one = self.splat(1);
                let ff = self.splat(255);
                let v = self.b.ins().iadd(s, one);
                self.b.ins().band(v, ff)
            }
            StencilOp::DecrWrap => {
                let one = self.splat(1);
                let ff = self.splat(255);
                let v = self.b.ins().isub(s, one);
                self.b.ins().band(v, ff)
            }
        };
        // Bit by bit: `mask & write mask ? new : s`, one select (a full
        // group's mask of all lanes is the write mask itself).
        let all = self.consts.iter().any(|&(k, v)| k == -1 && v == mask);
        let m = if all {
            u.stencil_write_mask
        } else {
            self.b.ins().band(mask, u.stencil_write_mask)
        };
        self.b.ins().bitselect(m, new, s)
    }

    fn load_depth(&mut self, format: DepthFormat, p: Value) -> Value {
        match format {
            DepthFormat::D16 => self.b.ins().uload16x4(mem(), p, 0),
            DepthFormat::D24 | DepthFormat::D32 | DepthFormat::D32F => self.b.ins().load(I32X4, mem(), p, 0),
        }
    }

    fn store_depth(&mut self, format: DepthFormat, p: Value, v: Value) {
        match format {
            DepthFormat::D16 => self.store_low_halves(p, v),
            DepthFormat::D24 | DepthFormat::D32 | DepthFormat::D32F => {
                self.b.ins().store(mem(), v, p, 0);
            }
        }
    }

    /// Stores the low 16 bits of each lane of `v` as four `u16` at `p`.
    fn store_low_halves(&mut self, p: Value, v: Value) {
        let m = self.splat(0xffff);
        let v = self.b.ins().band(v, m);
        let halves = self.b.ins().unarrow(v, v);
        let quads = self.b.ins().bitcast(types::I64X2, le(), halves);
        let q = self.b.ins().extractlane(quads, 0);
        self.b.ins().store(mem(), q, p, 0);
    }

    /// The stored colors of the group, packed as [`pixel::load`] reads them.
    fn load_dst(&mut self, g: &mut Group) -> Value {
        if let Some(d) = g.dst {
            return d;
        }
        let p = g.color_p;
        let d = match self.key.color_format {
            ColorFormat::Rgba8 | ColorFormat::Bgra8 => self.b.ins().load(I32X4, mem(), p, 0),
            ColorFormat::Rgb565 => self.b.ins().uload16x4(mem(), p, 0),
            ColorFormat::Rgb8 => {
                let lo = self.b.ins().load(types::I64, mem(), p, 0);
                let hi = self.b.ins().uload32(mem(), p, 8);
                let v = self.b.ins().scalar_to_vector(types::I64X2, lo);
                let v = self.b.ins().insertlane(v, hi, 1);
                let bytes = self.b.ins().bitcast(types::I8X16, le(), v);
                let zero = self.vconst_bytes([0; 16]);
                // Pixel i's three bytes into lane i, the fourth byte zero (index 16: from `zero`).
                let mask = [0, 1, 2, 16, 3, 4, 5, 16, 6, 7, 8, 16, 9, 10, 11, 16];
                let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
                let spread = self.b.ins().shuffle(bytes, zero, m);
                self.b.ins().bitcast(I32X4, le(), spread)
            }
            ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => {
                unreachable!("the deep formats' groups take `deep_stages`")
            }
        };
        g.dst = Some(d);
        d
    }

    fn store_color(&mut self, p: Value, v: Value) {
        match self.key.color_format {
            ColorFormat::Rgba8 | ColorFormat::Bgra8 => {
                self.b.ins().store(mem(), v, p, 0);
            }
            ColorFormat::Rgb565 => self.store_low_halves(p, v),
            ColorFormat::Rgb8 => {
                let bytes = self.b.ins().bitcast(types::I8X16, le(), v);
                let mask = [0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, 16, 16, 16, 16];
                let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
                let zero = self.vconst_bytes([0; 16]);
                let packed = self.b.ins().shuffle(bytes, zero, m);
                let quads = self.b.ins().bitcast(types::I64X2, le(), packed);
                let lo = self.b.ins().extractlane(quads, 0);
                self.b.ins().store(mem(), lo, p, 0);
                let words = self.b.ins().bitcast(I32X4, le(), packed);
                let hi = self.b.ins().extractlane(words, 2);
                self.b.ins().store(mem(), hi, p, 8);
            }
            ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => {
                unreachable!("the deep formats' groups take `deep_stages`")
            }
        }
    }

    /// `(v >> shift) & mask`.
    fn field(&mut self, v: Value, shift: i64, mask: i64) -> Value {
        let s = if shift == 0 {
            v
        } else {
            self.b.ins().ushr_imm_u(v, shift)
        };
        let m = self.splat(mask);
        self.b.ins().band(s, m)
    }

    /// Packed stored colors to RGBA bytes, as [`pixel::unpack`].
    fn unpack(&mut self, v: Value) -> [Value; 4] {
        match self.key.color_format {
            ColorFormat::Rgba8 => {
                let r = self.field(v, 0, 255);
                let g = self.field(v, 8, 255);
                let b = self.field(v, 16, 255);
                let a = self.b.ins().ushr_imm_u(v, 24);
                [r, g, b, a]
            }
            ColorFormat::Bgra8 => {
                let b = self.field(v, 0, 255);
                let g = self.field(v, 8, 255);
                let r = self.field(v, 16, 255);
                let a = self.b.ins().ushr_imm_u(v, 24);
                [r, g, b, a]
            }
            ColorFormat::Rgb8 => {
                let r = self.field(v, 0, 255);
                let g = self.field(v, 8, 255);
                let b = self.field(v, 16, 255);
                [r, g, b, self.splat(255)]
            }
            ColorFormat::Rgb565 => {
                let r5 = self.field(v, 11, 31);
                let g6 = self.field(v, 5, 63);
                let b5 = self.field(v, 0, 31);
                let r = self.replicate(r5, 3, 2);
                let g = self.replicate(g6, 2, 4);
                let b = self.replicate(b5, 3, 2);
                [r, g, b, self.splat(255)]
            }
            ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => {
                unreachable!("the deep formats' groups take `deep_stages`")
            }
        }
    }

    /// `(v << up) | (v >> down)`: bit replication to 8 bits.
    fn replicate(&mut self, v: Value, up: i64, down: i64) -> Value {
        let hi = self.b.ins().ishl_imm_u(v, up);
        let lo = self.b.ins().ushr_imm_u(v, down);
        self.b.ins().bor(hi, lo)
    }

    /// RGBA bytes to the format's packed value, as [`pixel::pack`]: `dither`
    /// holds the lanes' ordered-dither biases, or is `None` to truncate.
    fn pack(&mut self, [r, g, b, a]: [Value; 4], dither: Option<Value>) -> Value {
        let place = |s: &mut Self, v: Value, shift: i64| if shift == 0 { v } else { s.b.ins().ishl_imm_u(v, shift) };
        match self.key.color_format {
            ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8 => {
                let (c0, c2) = if self.key.color_format == ColorFormat::Bgra8 {
                    (b, r)
                } else {
                    (r, b)
                };
                let g8 = place(self, g, 8);
                let c2 = place(self, c2, 16);
                let v = self.b.ins().bor(c0, g8);
                let v = self.b.ins().bor(v, c2);
                // Alpha the colour mask keeps: its bits are the stored ones.
                if self.key.color_format.has_alpha() && self.key.color_mask.a {
                    let a = place(self, a, 24);
                    self.b.ins().bor(v, a)
                } else {
                    v
                }
            }
            ColorFormat::Rgb565 => {
                let [r, g, b] = match dither {
                    None => [
                        self.b.ins().ushr_imm_u(r, 3),
                        self.b.ins().ushr_imm_u(g, 2),
                        self.b.ins().ushr_imm_u(b, 3),
                    ],
                    Some(bias) => [
                        self.dither(r, 31, bias),
                        self.dither(g, 63, bias),
                        self.dither(b, 31, bias),
                    ],
                };
                let r = place(self, r, 11);
                let g = place(self, g, 5);
                let v = self.b.ins().bor(r, g);
                self.b.ins().bor(v, b)
            }
            ColorFormat::Rgba16
            | ColorFormat::Rgbx16
            | ColorFormat::Rgba16F
            | ColorFormat::Rgbx16F
            | ColorFormat::Rgba32F
            | ColorFormat::Rgbx32F => {
                unreachable!("the deep formats' groups take `deep_stages`")
            }
        }
    }

    /// `(c * max + bias) / 255`, as [`pixel::dither`]: for `n <= 65534`,
    /// `n / 255 == (n + 1 + (n >> 8)) >> 8` (checked over the range in tests).
    fn dither(&mut self, c: Value, max: i64, bias: Value) -> Value {
        let m = self.splat(max);
        let n = self.b.ins().imul(c, m);
        let n = self.b.ins().iadd(n, bias);
        let hi = self.b.ins().ushr_imm_u(n, 8);
        let n1 = self.b.ins().iadd(n, hi);
        let one = self.splat(1);
        let n1 = self.b.ins().iadd(n1, one);
        self.b.ins().ushr_imm_u(n1, 8)
    }

    fn logic_op(&mut self, op: LogicOp, s: Value, d: Value) -> Value {
        let b = &mut self.b;
        match op {
            LogicOp::Clear => self.splat(0),
            LogicOp::And => b.ins().band(s, d),
            LogicOp::AndReverse => b.ins().band_not(s, d),
            LogicOp::Copy => s,
            LogicOp::AndInverted => b.ins().band_not(d, s),
            LogicOp::Noop => d,
            LogicOp::Xor => b.ins().bxor(s, d),
            LogicOp::Or => b.ins().bor(s, d),
            LogicOp::Nor => {
                let v = b.ins().bor(s, d);
                b.ins().bnot(v)
            }
            LogicOp::Equiv => {
                let v = b.ins().bxor(s, d);
                b.ins().bnot(v)
            }
            LogicOp::Invert => b.ins().bnot(d),
            LogicOp::OrReverse => b.ins().bor_not(s, d),
            LogicOp::CopyInverted => b.ins().bnot(s),
            LogicOp::OrInverted => b.ins().bor_not(d, s),
            LogicOp::Nand => {
                let v = b.ins().band(s, d);
                b.ins().bnot(v)
            }
            LogicOp::Set => self.splat(-1),
        }
    }

    /// `x * f / 255` rounded as llvmpipe: `(t + (t >> 8) + 128) >> 8`, as
    /// [`pixel::mul_unorm8`], in 32-bit lanes or, with `lanes16`, in `u16`
    /// lanes: `x · f ≤ 65025` and `t + (t >> 8) + 128 ≤ 65407` fit, so the
    /// bits are the same.
    fn mul_unorm(&mut self, x: Value, f: Factor, lanes16: bool) -> Value {
        let splat = |g: &mut Self, v: u16| if lanes16 { g.splat16(v) } else { g.splat(i64::from(v)) };
        match f {
            Factor::Zero => splat(self, 0),
            // mul_unorm8(x, 255) == x for every byte x.
            Factor::One => x,
            Factor::Value(f) => {
                let t = self.b.ins().imul(x, f);
                let hi = self.b.ins().ushr_imm_u(t, 8);
                let t = self.b.ins().iadd(t, hi);
                let half = splat(self, 128);
                let t = self.b.ins().iadd(t, half);
                self.b.ins().ushr_imm_u(t, 8)
            }
        }
    }

    fn inv(&mut self, v: Value) -> Factor {
        if let Some(&(_, i)) = self.inverses.iter().find(|(k, _)| *k == v) {
            return Factor::Value(i);
        }
        let ff = self.splat(255);
        let i = self.b.ins().isub(ff, v);
        self.inverses.push((v, i));
        Factor::Value(i)
    }

    /// Factor `f` for channel `c`, as `interp::factor`.
    fn factor(&mut self, f: BlendFactor, c: usize, s: [Value; 4], d: [Value; 4], k: [Value; 4]) -> Factor {
        match f {
            BlendFactor::Zero => Factor::Zero,
            BlendFactor::One => Factor::One,
            BlendFactor::SrcColor => Factor::Value(s[c]),
            BlendFactor::OneMinusSrcColor => self.inv(s[c]),
            BlendFactor::DstColor => Factor::Value(d[c]),
            BlendFactor::OneMinusDstColor => self.inv(d[c]),
            BlendFactor::SrcAlpha => Factor::Value(s[3]),
            BlendFactor::OneMinusSrcAlpha => self.inv(s[3]),
            BlendFactor::DstAlpha => Factor::Value(d[3]),
            BlendFactor::OneMinusDstAlpha => self.inv(d[3]),
            BlendFactor::ConstantColor => Factor::Value(k[c]),
            BlendFactor::OneMinusConstantColor => self.inv(k[c]),
            BlendFactor::ConstantAlpha => Factor::Value(k[3]),
            BlendFactor::OneMinusConstantAlpha => self.inv(k[3]),
            BlendFactor::SrcAlphaSaturate => {
                if c == 3 {
                    Factor::One
                } else {
                    let ff = self.splat(255);
                    let ida = self.b.ins().isub(ff, d[3]);
                    Factor::Value(self.b.ins().umin(s[3], ida))
                }
            }
        }
    }

    /// A vector of eight `u16` lanes all `v`.
    fn splat16(&mut self, v: u16) -> Value {
        // Cached with the `i32` splats, under keys no `i32` constant has.
        let key = (1 << 40) | i64::from(v);
        if let Some(&(_, c)) = self.consts.iter().find(|(k, _)| *k == key) {
            return c;
        }
        let [lo, hi] = v.to_le_bytes();
        let bytes = std::array::from_fn(|i| if i % 2 == 0 { lo } else { hi });
        let c = self.vconst_bytes(bytes);
        let c = self.b.ins().bitcast(types::I16X8, le(), c);
        self.consts.push((key, c));
        c
    }

    /// Channels `a` and `b` (bytes in `i32` lanes) side by side in `u16` lanes.
    fn pair(&mut self, a: Value, b: Value, cache: &mut Vec<(Value, Value, Value)>) -> Value {
        if let Some(&(_, _, p)) = cache.iter().find(|&&(x, y, _)| x == a && y == b) {
            return p;
        }
        let p = self.b.ins().snarrow(a, b);
        cache.push((a, b, p));
        p
    }

    /// The factors of channels `c` and `c + 1` side by side.
    fn pair_factor(&mut self, (f0, f1): (Factor, Factor), cache: &mut Vec<(Value, Value, Value)>) -> Factor {
        match (f0, f1) {
            (Factor::Zero, Factor::Zero) => Factor::Zero,
            (Factor::One, Factor::One) => Factor::One,
            _ => {
                let v = |s: &mut Self, f: Factor| match f {
                    Factor::Zero => s.splat(0),
                    Factor::One => s.splat(255),
                    Factor::Value(v) => v,
                };
                let (a, b) = (v(self, f0), v(self, f1));
                Factor::Value(self.pair(a, b, cache))
            }
        }
    }

    /// [`Self::blend`] (same equation for colour and alpha) with two
    /// channels a vector: red and green, blue and alpha in the `u16` lanes
    /// of one vector each, which halves the arithmetic (`pmullw` where
    /// `pmulld` is slow). Leaves the group's colour packed for formats with
    /// a byte a channel, else as channels.
    fn blend16(&mut self, key: &BlendKey, g: &mut Group, dst: Value, u: &Uniforms) {
        let s = g.rgba;
        let d = self.unpack(dst);
        let k = u.blend_color;
        self.inverses.clear();
        let mut cache = Vec::new();
        let sp = [self.pair(s[0], s[1], &mut cache), self.pair(s[2], s[3], &mut cache)];
        let dp = match self.key.color_format {
            // Straight from the stored bytes: one shuffle a pair.
            ColorFormat::Rgba8 | ColorFormat::Bgra8 => {
                let at = match self.key.color_format {
                    ColorFormat::Rgba8 => [0u8, 1, 2, 3],
                    _ => [2, 1, 0, 3],
                };
                let bytes = self.b.ins().bitcast(types::I8X16, le(), dst);
                let zero = self.vconst_bytes([0; 16]);
                [0, 1].map(|p| {
                    // Index 16 takes a zero byte: lane j of the pair is
                    // channel `2p + j / 4` of pixel `j % 4`.
                    let mut mask = [16u8; 16];
                    for j in 0..8 {
                        mask[2 * j] = 4 * (j as u8 % 4) + at[2 * p + j / 4];
                    }
                    let m = self.b.func.dfg.immediates.push(mask.to_vec().into());
                    let v = self.b.ins().shuffle(bytes, zero, m);
                    self.b.ins().bitcast(types::I16X8, le(), v)
                })
            }
            _ => [self.pair(d[0], d[1], &mut cache), self.pair(d[2], d[3], &mut cache)],
        };
        let mut out = [sp[0], sp[1]];
        let eq = key.eq_rgb;
        for p in 0..2 {
            let (c0, c1) = (2 * p, 2 * p + 1);
            let params = |c: usize| {
                if c < 3 {
                    (key.src_rgb, key.dst_rgb)
                } else {
                    (key.src_alpha, key.dst_alpha)
                }
            };
            out[p] = match eq {
                BlendEquation::Min => self.b.ins().umin(sp[p], dp[p]),
                BlendEquation::Max => self.b.ins().umax(sp[p], dp[p]),
                BlendEquation::Add | BlendEquation::Subtract | BlendEquation::ReverseSubtract => {
                    let ((sf0, df0), (sf1, df1)) = (params(c0), params(c1));
                    let fs = (self.factor(sf0, c0, s, d, k), self.factor(sf1, c1, s, d, k));
                    let fs = self.pair_factor(fs, &mut cache);
                    let fd = (self.factor(df0, c0, s, d, k), self.factor(df1, c1, s, d, k));
                    let fd = self.pair_factor(fd, &mut cache);
                    let ws = self.mul_unorm(sp[p], fs, true);
                    let wd = self.mul_unorm(dp[p], fd, true);
                    self.blend_equation(eq, ws, wd, true)
                }
            };
        }
        let bytes = matches!(
            self.key.color_format,
            ColorFormat::Rgba8 | ColorFormat::Bgra8 | ColorFormat::Rgb8
        );
        if bytes {
            let planar = self.b.ins().unarrow(out[0], out[1]);
            g.packed = Some(self.interleave(planar));
        } else {
            g.rgba = [
                self.b.ins().uwiden_low(out[0]),
                self.b.ins().uwiden_high(out[0]),
                self.b.ins().uwiden_low(out[1]),
                self.b.ins().uwiden_high(out[1]),
            ];
        }
    }

    /// GL's blend equations with factors (add, subtract, reverse subtract;
    /// min and max take none) on the weighted source `ws` and
    /// destination `wd` unorm lanes (16-bit lanes when `lanes16`, else
    /// 32-bit), saturated to `0..=255`: one definition for both widths.
    fn blend_equation(&mut self, eq: BlendEquation, ws: Value, wd: Value, lanes16: bool) -> Value {
        let splat = |g: &mut Self, v: u16| if lanes16 { g.splat16(v) } else { g.splat(i64::from(v)) };
        if eq == BlendEquation::Add {
            let v = self.b.ins().iadd(ws, wd);
            let ff = splat(self, 255);
            return self.b.ins().umin(v, ff);
        }
        // Subtract, or (the callers' only other case) ReverseSubtract.
        let (a, b) = if eq == BlendEquation::Subtract {
            (ws, wd)
        } else {
            (wd, ws)
        };
        let v = self.b.ins().isub(a, b);
        let zero = splat(self, 0);
        self.b.ins().smax(v, zero)
    }

    fn blend(&mut self, key: &BlendKey, s: [Value; 4], d: [Value; 4], u: &Uniforms) -> [Value; 4] {
        let k = u.blend_color;
        self.inverses.clear();
        let mut out = s;
        // A channel the colour mask keeps (or the format does not store) is
        // not blended: its bits of the blended pixel are the stored ones
        // (the `ops` frame's alpha: a quarter of the blend).
        let mask = self.key.color_mask.for_format(self.key.color_format);
        let written = [mask.r, mask.g, mask.b, mask.a];
        for c in (0..4).filter(|&c| written[c]) {
            let (sf, df, eq) = if c < 3 {
                (key.src_rgb, key.dst_rgb, key.eq_rgb)
            } else {
                (key.src_alpha, key.dst_alpha, key.eq_alpha)
            };
            out[c] = match eq {
                BlendEquation::Min => self.b.ins().umin(s[c], d[c]),
                BlendEquation::Max => self.b.ins().umax(s[c], d[c]),
                BlendEquation::Add | BlendEquation::Subtract | BlendEquation::ReverseSubtract => {
                    let fs = self.factor(sf, c, s, d, k);
                    let fd = self.factor(df, c, s, d, k);
                    let ws = self.mul_unorm(s[c], fs, false);
                    let wd = self.mul_unorm(d[c], fd, false);
                    self.blend_equation(eq, ws, wd, false)
                }
            };
        }
        out
    }
}

/// Uniform values splatted once per span, for the stages that read them.
struct Uniforms {
    alpha_ref: Value,
    stencil_ref: Value,
    stencil_ref_masked: Value,
    stencil_value_mask: Value,
    stencil_write_mask: Value,
    blend_color: [Value; 4],
    dither: Value,
}

impl Uniforms {
    fn load(g: &mut Gen<'_>, u: Value, call: Value) -> Uniforms {
        let key = g.key;
        let zero = g.splat(0);
        let mut out = Uniforms {
            alpha_ref: zero,
            stencil_ref: zero,
            stencil_ref_masked: zero,
            stencil_value_mask: zero,
            stencil_write_mask: zero,
            blend_color: [zero; 4],
            dither: zero,
        };
        // Each one aligned vector load of its four lanes, made once a batch
        // by `SplatUniforms::new`.
        let load = |g: &mut Gen<'_>, off: usize| g.b.ins().load(I32X4, mem().with_aligned(), u, off as i32);
        // The deep formats' stages read their own (`DeepUniforms`).
        let deep = key.color_format.is_deep();
        if key.alpha_test.is_some() && !deep {
            out.alpha_ref = load(g, offset_of!(SplatUniforms, alpha_ref));
        }
        if let (Some(st), true) = (key.stencil, key.stencil_buffer) {
            // What the test and the ops read (the loads are not removed when unused).
            let ops = [st.fail, st.zfail, st.zpass];
            if ops.contains(&StencilOp::Replace) {
                out.stencil_ref = load(g, offset_of!(SplatUniforms, stencil_ref));
            }
            if !matches!(st.func, CompareFunc::Always | CompareFunc::Never) {
                out.stencil_value_mask = load(g, offset_of!(SplatUniforms, stencil_value_mask));
                out.stencil_ref_masked = load(g, offset_of!(SplatUniforms, stencil_ref_masked));
            }
            if ops.iter().any(|&op| op != StencilOp::Keep) {
                out.stencil_write_mask = load(g, offset_of!(SplatUniforms, stencil_write_mask));
            }
        }
        let constant = |f: BlendFactor| {
            matches!(
                f,
                BlendFactor::ConstantColor
                    | BlendFactor::OneMinusConstantColor
                    | BlendFactor::ConstantAlpha
                    | BlendFactor::OneMinusConstantAlpha
            )
        };
        // Only blends that read the constant colour load it (the loads are
        // not removed when unused).
        if !deep
            && key.blend.is_some_and(|b| {
                [b.src_rgb, b.dst_rgb, b.src_alpha, b.dst_alpha]
                    .into_iter()
                    .any(constant)
            })
        {
            for c in 0..4 {
                out.blend_color[c] = load(g, offset_of!(SplatUniforms, blend_color) + 16 * c);
            }
        }
        if key.dither && key.color_format.is_reduced() {
            out.dither = g.b.ins().load(I32X4, mem(), call, offset_of!(SpanCall, dither) as i32);
        }
        out
    }
}

/// What a specialist's second argument points to: the integer uniforms the
/// stages compare and select with, each in four lanes, then the
/// [`FragmentUniforms`] themselves (which the shading stage reads as
/// scalars). Made once a batch of spans (`Specialist::run_splatted`), so
/// that a group loads each in one aligned vector load where loading,
/// moving and splatting a scalar took 3 instructions (the `ops` frame's
/// groups: 2 uniforms, 4 instructions fewer).
#[repr(C, align(16))]
#[derive(Clone, Copy, Debug)]
pub struct SplatUniforms {
    pub alpha_ref: [u32; 4],
    pub stencil_ref: [u32; 4],
    /// `stencil_ref & stencil_value_mask`.
    pub stencil_ref_masked: [u32; 4],
    pub stencil_value_mask: [u32; 4],
    pub stencil_write_mask: [u32; 4],
    /// R, G, B, A, each in four lanes.
    pub blend_color: [[u32; 4]; 4],
    /// The fog parameters (`FogUniforms::params`, f32 bits), then the
    /// third and fourth negated (`-(c·p) == c·(-p)` bit for bit: no `fneg`
    /// a group), each in four lanes.
    pub fog_params: [[u32; 4]; 6],
    /// The fog colour's R, G, B (f32 bits), each in four lanes.
    pub fog_color: [[u32; 4]; 3],
    pub uniforms: FragmentUniforms,
}

impl SplatUniforms {
    pub fn new(u: &FragmentUniforms) -> SplatUniforms {
        let lanes = |v: u8| [u32::from(v); 4];
        SplatUniforms {
            alpha_ref: lanes(u.alpha_ref),
            stencil_ref: lanes(u.stencil_ref),
            stencil_ref_masked: lanes(u.stencil_ref & u.stencil_value_mask),
            stencil_value_mask: lanes(u.stencil_value_mask),
            stencil_write_mask: lanes(u.stencil_write_mask),
            blend_color: u.blend_color.map(lanes),
            fog_params: {
                let p = u.fog.params;
                let sign = 0x8000_0000;
                [p[0], p[1], p[2], p[3], p[2] ^ sign, p[3] ^ sign].map(|v| [v; 4])
            },
            fog_color: u.fog.color.map(|v| [v; 4]),
            uniforms: *u,
        }
    }
}

/// The offset of `FragmentUniforms` field offset `off` from a specialist's
/// second argument.
pub(crate) const fn uniform_offset(off: usize) -> usize {
    offset_of!(SplatUniforms, uniforms) + off
}

#[cfg(test)]
mod disasm {
    //! The machine code of the benchmark frames' keys, printed by
    //! `cargo test -p softgl-jit --lib disasm -- --ignored --nocapture`: for
    //! counting instructions a group while tuning the generator.
    use super::*;
    use crate::key::{BlendKey, DepthKey, ShadeKey, StencilKey};

    /// The `fill` frame's key (smooth colour, no tests), the `ops` frame's
    /// and the `tex` frame's.
    fn keys() -> [(&'static str, FragmentKey); 4] {
        let base = FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true);
        let shade = ShadeKey {
            color: true,
            ..ShadeKey::default()
        };
        let fill = FragmentKey {
            shade: Some(shade),
            ..base
        };
        let depth = DepthKey {
            func: CompareFunc::Less,
            write: true,
        };
        let tris = FragmentKey {
            depth: Some(depth),
            shade: Some(ShadeKey { depth: true, ..shade }),
            ..base
        };
        let ops = FragmentKey {
            scissor: true,
            alpha_test: Some(CompareFunc::Greater),
            stencil: Some(StencilKey {
                func: CompareFunc::Always,
                fail: StencilOp::Keep,
                zfail: StencilOp::Incr,
                zpass: StencilOp::Incr,
            }),
            blend: Some(BlendKey::OVER),
            color_mask: ColorMask {
                r: true,
                g: true,
                b: true,
                a: false,
            },
            ..tris
        };
        use crate::texture::{
            effective_combine, BaseFormat, CombineKey, DepthMode, EnvMode, Filter, MipFilter, SamplerKey,
            SamplerStatics, TexTarget, TexUnitKey, TexelFormat, Wrap, MAX_UNITS,
        };
        let unit = TexUnitKey {
            sampler: SamplerKey {
                target: TexTarget::D2,
                format: TexelFormat::Rgba8,
                min: Filter::Linear,
                mip: MipFilter::Linear,
                mag: Filter::Linear,
                wrap: [Wrap::Repeat; 3],
                compare: None,
                depth_mode: DepthMode::Luminance,
                statics: SamplerStatics {
                    pot: [true; 2],
                    ..SamplerStatics::default()
                },
            },
            base: BaseFormat::Rgba,
            env: effective_combine(EnvMode::Modulate, BaseFormat::Rgba, CombineKey::DEFAULT),
        };
        let mut units = [None; MAX_UNITS];
        units[0] = Some(unit);
        let tex = FragmentKey {
            shade: Some(ShadeKey {
                tex: units,
                fog: Some(crate::shade::FogMode::Exp),
                ..ShadeKey { depth: true, ..shade }
            }),
            ..tris
        };
        [("fill", fill), ("tris", tris), ("ops", ops), ("tex", tex)]
    }

    #[test]
    #[ignore = "prints machine code; run by hand"]
    fn print() {
        let isa = host_isa().unwrap();
        for (name, key) in keys() {
            let mut ctx = cranelift_codegen::Context::new();
            ctx.func.signature = signature(&isa);
            build(&key, &isa, &mut ctx.func);
            ctx.set_disasm(true);
            let code = ctx
                .compile(&*isa, &mut cranelift_codegen::control::ControlPlane::default())
                .unwrap();
            let text = code.vcode.clone().unwrap_or_default();
            println!("==== {name}: {} bytes\n{text}", code.code_info().total_size);
        }
    }

    /// The median time of building and compiling each key (without the
    /// disassembly), for keeping compile time in view.
    #[test]
    #[ignore = "times compiles; run by hand"]
    fn compile_time() {
        let isa = host_isa().unwrap();
        let mut fctx = FunctionBuilderContext::new();
        for (name, key) in keys() {
            let mut times: Vec<_> = (0..31)
                .map(|_| {
                    let t = std::time::Instant::now();
                    let mut ctx = cranelift_codegen::Context::new();
                    ctx.func.signature = signature(&isa);
                    build_with(&key, &isa, &mut ctx.func, (&mut fctx, true));
                    ctx.compile(&*isa, &mut cranelift_codegen::control::ControlPlane::default())
                        .unwrap();
                    t.elapsed()
                })
                .collect();
            times.sort();
            println!("{name}: {:?}", times[15]);
        }
    }
}
