//! Which vector widths Cranelift compiles on this host. Specialists use groups
//! of four `i32` lanes because 128 bits is the widest x86-64 Cranelift lowers,
//! even on CPUs with AVX2 and AVX-512 (this machine has both; Cranelift uses
//! their VEX encodings for the 128-bit operations). If this test starts to
//! fail because `i32x8` compiles, wider groups have become available: widen
//! `compile.rs`'s groups to eight lanes.

use cranelift_codegen::ir::{types, AbiParam, InstBuilder, MemFlagsData, Signature, Type};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};

/// Compiles `p[0] = p[0] + p[0]` on vectors of type `ty`.
fn compiles(ty: Type) -> bool {
    let isa = softgl_jit::compile::host_isa().expect("a Cranelift back end for this host");
    let mut ctx = cranelift_codegen::Context::new();
    let mut sig = Signature::new(isa.default_call_conv());
    sig.params.push(AbiParam::new(isa.pointer_type()));
    ctx.func.signature = sig;
    let mut fctx = FunctionBuilderContext::new();
    let mut b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
    let entry = b.create_block();
    b.append_block_params_for_function_params(entry);
    b.switch_to_block(entry);
    let p = b.block_params(entry)[0];
    let v = b.ins().load(ty, MemFlagsData::new(), p, 0);
    let w = b.ins().iadd(v, v);
    b.ins().store(MemFlagsData::new(), w, p, 0);
    b.ins().return_(&[]);
    b.seal_all_blocks();
    b.finalize(isa.frontend_config());
    let mut ctrl = Default::default();
    ctx.compile(&*isa, &mut ctrl).is_ok()
}

#[test]
fn widest_vectors_are_128_bits() {
    assert!(
        compiles(types::I32X4),
        "i32x4 must compile: specialists are built from it"
    );
    if cfg!(target_arch = "x86_64") {
        assert!(
            !compiles(types::I32X8),
            "i32x8 compiles now: widen the specialist groups"
        );
    }
}
