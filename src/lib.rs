//! softgl: a software OpenGL 1.x fixed-function renderer for offscreen rendering.
//!
//! [`Context`] is a GL-shaped state machine drawing into its own
//! [`Framebuffer`]: geometry (transform, clip, cull) in [`geometry`],
//! rasterization following GL's rules in [`raster`], and the per-fragment
//! stages from the `softgl-jit` crate. Errors are [`GlError`] values.
//!
//! ```
//! use softgl::{Context, FramebufferDesc, PrimitiveMode, ClearMask};
//! let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap();
//! gl.clear(ClearMask::COLOR).unwrap();
//! gl.begin(PrimitiveMode::Triangles).unwrap();
//! gl.color3(1.0, 0.0, 0.0);
//! gl.vertex2(-1.0, -1.0);
//! gl.vertex2(3.0, -1.0);
//! gl.vertex2(-1.0, 3.0);
//! gl.end().unwrap();
//! assert_eq!(gl.framebuffer().pixel(4, 4), Some([255, 0, 0, 255]));
//! ```
#![forbid(unsafe_code)]

pub mod accum;
pub mod buffer;
pub mod clip_control;
pub mod context;
pub mod demo;
pub mod error;
pub mod eval;
pub mod fbo;
pub mod fog;
pub mod fragment;
pub mod framebuffer;
pub mod geometry;
pub mod gl_enum;
pub(crate) mod immediate;
pub mod inverse;
pub mod lighting;
pub mod matrix;
pub mod multisample;
pub mod names;
pub mod pixel_rect;
pub mod pixel_shade;
pub mod pixel_transfer;
pub mod query;
pub mod raster;
pub mod raster_pos;
pub mod select;
pub mod state;
pub mod texture;
pub mod tracked;

pub use accum::{AccumBuffer, AccumOp};
pub use buffer::{Buffer, BufferAccess, BufferParamName, BufferStore, BufferTarget, BufferUsage};
pub use clip_control::{ClipControl, ClipDepthMode, ClipOrigin};
pub use context::{AttribArray, Context, CurrentAttribs, Indices, SceneStats, VertexArrays};
pub use error::{GlError, GlResult};
pub use fog::{FogCoordSrc, FogMode, FogParam};
pub use fragment::Backend;
pub use framebuffer::{Clear, ColorMemory, Framebuffer, FramebufferDesc, ReadFormat};
pub use gl_enum::GlEnum;
pub use lighting::{
    ColorControl, ColorMaterialMode, LightModelParam, LightParam, LightParamName, MaterialParam, MaterialParamName,
};
pub use matrix::MatrixMode;
pub use query::{QueryObjectParam, QueryParam, QueryStore, QueryTarget};
pub use softgl_jit::rng;
pub use softgl_jit::{
    BlendEquation, BlendFactor, CacheStats, ColorFormat, ColorMask, CompareFunc, DepthFormat, FragmentKey, LogicOp,
    ShadeKey, StencilOp,
};
pub use state::{Capability, ClearMask, Face, FrontFace, PolygonMode, PrimitiveMode, ShadeModel};
pub use texture::unit::{
    TexCoordName, TexEnvParam, TexEnvParamName, TexGenMode, TexGenParam, TexGenParamName, TexUnit, TextureUnits,
};
pub use texture::{
    BaseFormat, CombineFn, CombineSrc, DepthMode, EnvMode, Filter, InternalFormat, MipFilter, Operand, PixelData,
    PixelFormat, PixelStore, PixelType, Sampling, TexImageTarget, TexLevelParamName, TexParam, TexParamName,
    TextureStore, TextureTarget, Wrap,
};
