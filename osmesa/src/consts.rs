//! The GL and OSMesa enumerants this library reads and returns (values from
//! Mesa's `GL/gl.h`, `GL/glext.h` and `GL/osmesa.h`).
#![allow(missing_docs)]

pub type GLenum = u32;

/// Largest buffer side `OSMesaMakeCurrent` takes (Mesa's `OSMESA_MAX_WIDTH`).
pub const MAX_SIZE: i32 = 16384;

pub const OSMESA_COLOR_INDEX: GLenum = 0x1900;
pub const OSMESA_RGBA: GLenum = 0x1908;
pub const OSMESA_BGRA: GLenum = 0x1;
pub const OSMESA_ARGB: GLenum = 0x2;
pub const OSMESA_RGB: GLenum = 0x1907;
pub const OSMESA_BGR: GLenum = 0x4;
pub const OSMESA_RGB_565: GLenum = 0x5;
pub const OSMESA_ROW_LENGTH: i32 = 0x10;
pub const OSMESA_Y_UP: i32 = 0x11;
pub const OSMESA_WIDTH: i32 = 0x20;
pub const OSMESA_HEIGHT: i32 = 0x21;
pub const OSMESA_FORMAT: i32 = 0x22;
pub const OSMESA_TYPE: i32 = 0x23;
pub const OSMESA_MAX_WIDTH: i32 = 0x24;
pub const OSMESA_MAX_HEIGHT: i32 = 0x25;
pub const OSMESA_DEPTH_BITS: i32 = 0x30;
pub const OSMESA_STENCIL_BITS: i32 = 0x31;
pub const OSMESA_ACCUM_BITS: i32 = 0x32;
pub const OSMESA_PROFILE: i32 = 0x33;
pub const OSMESA_CORE_PROFILE: i32 = 0x34;
pub const OSMESA_COMPAT_PROFILE: i32 = 0x35;
pub const OSMESA_CONTEXT_MAJOR_VERSION: i32 = 0x36;
pub const OSMESA_CONTEXT_MINOR_VERSION: i32 = 0x37;

pub const GL_NO_ERROR: GLenum = 0;
pub const GL_FALSE: u8 = 0;
pub const GL_TRUE: u8 = 1;

// Data types.
pub const GL_BYTE: GLenum = 0x1400;
pub const GL_UNSIGNED_BYTE: GLenum = 0x1401;
pub const GL_SHORT: GLenum = 0x1402;
pub const GL_UNSIGNED_SHORT: GLenum = 0x1403;
pub const GL_INT: GLenum = 0x1404;
pub const GL_UNSIGNED_INT: GLenum = 0x1405;
pub const GL_FLOAT: GLenum = 0x1406;
pub const GL_DOUBLE: GLenum = 0x140A;
pub const GL_UNSIGNED_SHORT_5_6_5: GLenum = 0x8363;

// Pixel formats.
pub const GL_COLOR_INDEX: GLenum = 0x1900;
pub const GL_STENCIL_INDEX: GLenum = 0x1901;
pub const GL_DEPTH_COMPONENT: GLenum = 0x1902;
pub const GL_DEPTH_STENCIL: GLenum = 0x84F9;
pub const GL_UNSIGNED_INT_24_8: GLenum = 0x84FA;
pub const GL_FLOAT_32_UNSIGNED_INT_24_8_REV: GLenum = 0x8DAD;
pub const GL_DEPTH_COMPONENT32F: GLenum = 0x8CAC;
pub const GL_DEPTH32F_STENCIL8: GLenum = 0x8CAD;
pub const GL_RED: GLenum = 0x1903;
pub const GL_GREEN: GLenum = 0x1904;
pub const GL_BLUE: GLenum = 0x1905;
pub const GL_ALPHA: GLenum = 0x1906;
pub const GL_RGB: GLenum = 0x1907;
pub const GL_RGBA: GLenum = 0x1908;
pub const GL_LUMINANCE: GLenum = 0x1909;
pub const GL_LUMINANCE_ALPHA: GLenum = 0x190A;
pub const GL_BGR: GLenum = 0x80E0;
pub const GL_BGRA: GLenum = 0x80E1;

// Clear bits.
pub const GL_DEPTH_BUFFER_BIT: u32 = 0x100;
pub const GL_ACCUM_BUFFER_BIT: u32 = 0x200;
pub const GL_STENCIL_BUFFER_BIT: u32 = 0x400;
pub const GL_COLOR_BUFFER_BIT: u32 = 0x4000;

// Strings.
pub const GL_VENDOR: GLenum = 0x1F00;
pub const GL_RENDERER: GLenum = 0x1F01;
pub const GL_VERSION: GLenum = 0x1F02;
pub const GL_EXTENSIONS: GLenum = 0x1F03;

// Buffers.
pub const GL_NONE: GLenum = 0;
pub const GL_FRONT_LEFT: GLenum = 0x400;
pub const GL_FRONT_RIGHT: GLenum = 0x401;
pub const GL_BACK_LEFT: GLenum = 0x402;
pub const GL_BACK_RIGHT: GLenum = 0x403;
pub const GL_FRONT: GLenum = 0x404;
pub const GL_BACK: GLenum = 0x405;
pub const GL_LEFT: GLenum = 0x406;
pub const GL_RIGHT: GLenum = 0x407;
pub const GL_FRONT_AND_BACK: GLenum = 0x408;

// Client arrays.
pub const GL_VERTEX_ARRAY: GLenum = 0x8074;
pub const GL_NORMAL_ARRAY: GLenum = 0x8075;
pub const GL_COLOR_ARRAY: GLenum = 0x8076;
pub const GL_INDEX_ARRAY: GLenum = 0x8077;
pub const GL_TEXTURE_COORD_ARRAY: GLenum = 0x8078;
pub const GL_EDGE_FLAG_ARRAY: GLenum = 0x8079;
pub const GL_VERTEX_ARRAY_POINTER: GLenum = 0x808E;
pub const GL_NORMAL_ARRAY_POINTER: GLenum = 0x808F;
pub const GL_COLOR_ARRAY_POINTER: GLenum = 0x8090;
pub const GL_TEXTURE_COORD_ARRAY_POINTER: GLenum = 0x8092;
pub const GL_EDGE_FLAG_ARRAY_POINTER: GLenum = 0x8093;

// Hints.
pub const GL_PERSPECTIVE_CORRECTION_HINT: GLenum = 0x0C50;
pub const GL_POINT_SMOOTH_HINT: GLenum = 0x0C51;
pub const GL_LINE_SMOOTH_HINT: GLenum = 0x0C52;
pub const GL_POLYGON_SMOOTH_HINT: GLenum = 0x0C53;
pub const GL_FOG_HINT: GLenum = 0x0C54;
pub const GL_DONT_CARE: GLenum = 0x1100;
pub const GL_FASTEST: GLenum = 0x1101;
pub const GL_NICEST: GLenum = 0x1102;

// Pixel store.
pub const GL_UNPACK_SWAP_BYTES: GLenum = 0x0CF0;
pub const GL_UNPACK_LSB_FIRST: GLenum = 0x0CF1;
pub const GL_UNPACK_ROW_LENGTH: GLenum = 0x0CF2;
pub const GL_UNPACK_SKIP_ROWS: GLenum = 0x0CF3;
pub const GL_UNPACK_SKIP_PIXELS: GLenum = 0x0CF4;
pub const GL_UNPACK_ALIGNMENT: GLenum = 0x0CF5;
pub const GL_PACK_SWAP_BYTES: GLenum = 0x0D00;
pub const GL_PACK_LSB_FIRST: GLenum = 0x0D01;
pub const GL_PACK_ROW_LENGTH: GLenum = 0x0D02;
pub const GL_PACK_SKIP_ROWS: GLenum = 0x0D03;
pub const GL_PACK_SKIP_PIXELS: GLenum = 0x0D04;
pub const GL_PACK_ALIGNMENT: GLenum = 0x0D05;
pub const GL_PACK_SKIP_IMAGES: GLenum = 0x806B;
pub const GL_PACK_IMAGE_HEIGHT: GLenum = 0x806C;
pub const GL_UNPACK_SKIP_IMAGES: GLenum = 0x806D;
pub const GL_UNPACK_IMAGE_HEIGHT: GLenum = 0x806E;

// Texturing.
pub const GL_TEXTURE_1D: GLenum = 0x0DE0;
pub const GL_TEXTURE_2D: GLenum = 0x0DE1;
pub const GL_TEXTURE_3D: GLenum = 0x806F;
pub const GL_TEXTURE_CUBE_MAP: GLenum = 0x8513;
pub const GL_TEXTURE_CUBE_MAP_POSITIVE_X: GLenum = 0x8515;
pub const GL_TEXTURE_CUBE_MAP_NEGATIVE_Z: GLenum = 0x851A;
pub const GL_PROXY_TEXTURE_1D: GLenum = 0x8063;
pub const GL_PROXY_TEXTURE_2D: GLenum = 0x8064;
pub const GL_PROXY_TEXTURE_3D: GLenum = 0x8070;
pub const GL_PROXY_TEXTURE_CUBE_MAP: GLenum = 0x851B;
pub const GL_TEXTURE_BINDING_1D: GLenum = 0x8068;
pub const GL_TEXTURE_BINDING_2D: GLenum = 0x8069;
pub const GL_TEXTURE_BINDING_3D: GLenum = 0x806A;
pub const GL_TEXTURE_BINDING_CUBE_MAP: GLenum = 0x8514;
pub const GL_TEXTURE_RECTANGLE_ARB: GLenum = 0x84F5;
pub const GL_TEXTURE_BINDING_RECTANGLE_ARB: GLenum = 0x84F6;
pub const GL_PROXY_TEXTURE_RECTANGLE_ARB: GLenum = 0x84F7;
pub const GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB: GLenum = 0x84F8;
pub const GL_TEXTURE0: GLenum = 0x84C0;
pub const GL_ACTIVE_TEXTURE: GLenum = 0x84E0;
pub const GL_CLIENT_ACTIVE_TEXTURE: GLenum = 0x84E1;
pub const GL_MAX_TEXTURE_UNITS: GLenum = 0x84E2;
pub const GL_MAX_TEXTURE_SIZE: GLenum = 0x0D33;
pub const GL_MAX_3D_TEXTURE_SIZE: GLenum = 0x8073;
pub const GL_MAX_CUBE_MAP_TEXTURE_SIZE: GLenum = 0x851C;
pub const GL_MAX_TEXTURE_LOD_BIAS: GLenum = 0x84FD;
pub const GL_TEXTURE_GEN_S: GLenum = 0x0C60;
pub const GL_TEXTURE_GEN_Q: GLenum = 0x0C63;
pub const GL_TEXTURE_COMPRESSION_HINT: GLenum = 0x84EF;
pub const GL_GENERATE_MIPMAP_HINT: GLenum = 0x8192;
pub const GL_TEXTURE_ENV: GLenum = 0x2300;
pub const GL_TEXTURE_FILTER_CONTROL: GLenum = 0x8500;
pub const GL_S: GLenum = 0x2000;
pub const GL_Q: GLenum = 0x2003;
pub const GL_NUM_COMPRESSED_TEXTURE_FORMATS: GLenum = 0x86A2;
pub const GL_COMPRESSED_TEXTURE_FORMATS: GLenum = 0x86A3;
pub const GL_TEXTURE_COORD_ARRAY_SIZE: GLenum = 0x8088;
pub const GL_TEXTURE_COORD_ARRAY_TYPE: GLenum = 0x8089;
pub const GL_TEXTURE_COORD_ARRAY_STRIDE: GLenum = 0x808A;
pub const GL_CURRENT_TEXTURE_COORDS: GLenum = 0x0B03;
