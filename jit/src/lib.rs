//! softgl's per-fragment stages.
//!
//! A [`FragmentKey`] says which stages are on and how they are configured; the
//! [`FragmentUniforms`] carry the values that change often. The interpreter in
//! [`interp`] is the reference semantics: it runs the key's [`Stage`]s over
//! [`FragmentSpan`]s into a [`Target`]. A compiled back end (Cranelift) must leave
//! the buffers bit-identical to it.
#![deny(unsafe_code)]

pub mod cache;
#[allow(unsafe_code)]
pub mod callout;
pub mod compile;
pub mod deep;
pub mod interp;
pub mod key;
pub mod pixel;
pub mod rng;
pub mod shade;
pub mod span;
#[allow(unsafe_code)]
pub mod specialist;
pub mod target;
pub mod texture;
pub mod tier;
pub mod uniforms;

pub use cache::{CacheStats, SpecialistCache};
pub use interp::FragmentError;
pub use key::{
    BlendEquation, BlendFactor, BlendKey, ColorFormat, ColorMask, CompareFunc, DepthFormat, DepthKey, FragmentKey,
    KeyError, LogicOp, ShadeKey, Stage, StencilKey, StencilOp,
};
pub use shade::{FogMode, FogUniforms, Planes};
pub use span::{FragmentSpan, SPAN_MAX};
pub use specialist::{DrawTextures, Specialist, SpecialistError};
pub use target::{DepthTarget, Target, TargetError};
pub use texture::TextureSet;
pub use tier::Tier;
pub use uniforms::{DeepUniforms, FragmentUniforms};
