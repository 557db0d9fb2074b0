//! GL enumerants of softgl's state types, written once: each type's variants
//! with their GL name and value (Mesa's `GL/gl.h`, `GL/glext.h`). The C ABI
//! (`softgl-osmesa`) decodes C's arguments and encodes query answers with it,
//! and the conformance back ends that speak C GL encode their calls with it.
//!
//! The one list per type generates an exhaustive `match` for [`GlEnum::to_gl`]
//! (a new variant without a value does not compile) and a `match` for
//! [`GlEnum::from_gl`] (a value listed twice is an unreachable-pattern lint).

use crate::buffer::{BufferAccess, BufferParamName, BufferTarget, BufferUsage};
use crate::fog::{FogCoordSrc, FogMode};
use crate::lighting::{ColorControl, ColorMaterialMode, LightParamName, MaterialParamName};
use crate::matrix::MatrixMode;
use crate::query::{QueryObjectParam, QueryParam, QueryTarget};
use crate::state::{Capability, Face, FrontFace, PolygonMode, PrimitiveMode, ShadeModel};
use crate::texture::unit::{TexCoordName, TexGenMode};
use softgl_jit::texture::{CombineFn, CombineSrc, EnvMode, Operand};
use softgl_jit::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};

/// A softgl type that stands for a set of GL enumerants.
pub trait GlEnum: Copy + Eq + std::fmt::Debug + 'static {
    /// Every variant with its GL name and value, in GL's order.
    const TABLE: &'static [(Self, &'static str, u32)];
    /// The GL value.
    fn to_gl(self) -> u32;
    /// The variant whose GL value is `value`; `None` for any other value
    /// (`GL_INVALID_ENUM` at the C ABI).
    fn from_gl(value: u32) -> Option<Self>;
    /// The GL name (`"GL_LESS"`).
    fn gl_name(self) -> &'static str {
        Self::TABLE
            .iter()
            .find(|(v, _, _)| *v == self)
            .map_or("", |&(_, name, _)| name)
    }
}

macro_rules! gl_enums {
    ($($ty:ident { $($variant:ident $(($($arg:tt)+))? = $name:ident $value:literal,)* })*) => {
        $(
            impl GlEnum for $ty {
                const TABLE: &'static [(Self, &'static str, u32)] =
                    &[$(($ty::$variant $(($($arg)+))?, stringify!($name), $value)),*];
                fn to_gl(self) -> u32 {
                    match self {
                        $($ty::$variant $(($($arg)+))? => $value,)*
                        // Still exhaustive over the variants: a tuple variant
                        // (`Light(8)`) outside its listed values has no GL value.
                        $(#[allow(unreachable_patterns)] $ty::$variant { .. } => 0,)*
                    }
                }
                fn from_gl(value: u32) -> Option<Self> {
                    match value {
                        $($value => Some($ty::$variant $(($($arg)+))?),)*
                        _ => None,
                    }
                }
            }
        )*
    };
}

gl_enums! {
    QueryTarget {
        SamplesPassed = GL_SAMPLES_PASSED 0x8914,
    }
    QueryParam {
        CounterBits = GL_QUERY_COUNTER_BITS 0x8864,
        CurrentQuery = GL_CURRENT_QUERY 0x8865,
    }
    QueryObjectParam {
        Result = GL_QUERY_RESULT 0x8866,
        ResultAvailable = GL_QUERY_RESULT_AVAILABLE 0x8867,
    }
    BufferTarget {
        Array = GL_ARRAY_BUFFER 0x8892,
        ElementArray = GL_ELEMENT_ARRAY_BUFFER 0x8893,
    }
    BufferUsage {
        StreamDraw = GL_STREAM_DRAW 0x88E0,
        StreamRead = GL_STREAM_READ 0x88E1,
        StreamCopy = GL_STREAM_COPY 0x88E2,
        StaticDraw = GL_STATIC_DRAW 0x88E4,
        StaticRead = GL_STATIC_READ 0x88E5,
        StaticCopy = GL_STATIC_COPY 0x88E6,
        DynamicDraw = GL_DYNAMIC_DRAW 0x88E8,
        DynamicRead = GL_DYNAMIC_READ 0x88E9,
        DynamicCopy = GL_DYNAMIC_COPY 0x88EA,
    }
    BufferAccess {
        ReadOnly = GL_READ_ONLY 0x88B8,
        WriteOnly = GL_WRITE_ONLY 0x88B9,
        ReadWrite = GL_READ_WRITE 0x88BA,
    }
    BufferParamName {
        Size = GL_BUFFER_SIZE 0x8764,
        Usage = GL_BUFFER_USAGE 0x8765,
        Access = GL_BUFFER_ACCESS 0x88BB,
        Mapped = GL_BUFFER_MAPPED 0x88BC,
    }
    PrimitiveMode {
        Points = GL_POINTS 0x0000,
        Lines = GL_LINES 0x0001,
        LineLoop = GL_LINE_LOOP 0x0002,
        LineStrip = GL_LINE_STRIP 0x0003,
        Triangles = GL_TRIANGLES 0x0004,
        TriangleStrip = GL_TRIANGLE_STRIP 0x0005,
        TriangleFan = GL_TRIANGLE_FAN 0x0006,
        Quads = GL_QUADS 0x0007,
        QuadStrip = GL_QUAD_STRIP 0x0008,
        Polygon = GL_POLYGON 0x0009,
    }
    CompareFunc {
        Never = GL_NEVER 0x0200,
        Less = GL_LESS 0x0201,
        Equal = GL_EQUAL 0x0202,
        Lequal = GL_LEQUAL 0x0203,
        Greater = GL_GREATER 0x0204,
        Notequal = GL_NOTEQUAL 0x0205,
        Gequal = GL_GEQUAL 0x0206,
        Always = GL_ALWAYS 0x0207,
    }
    StencilOp {
        Zero = GL_ZERO 0x0000,
        Invert = GL_INVERT 0x150A,
        Keep = GL_KEEP 0x1E00,
        Replace = GL_REPLACE 0x1E01,
        Incr = GL_INCR 0x1E02,
        Decr = GL_DECR 0x1E03,
        IncrWrap = GL_INCR_WRAP 0x8507,
        DecrWrap = GL_DECR_WRAP 0x8508,
    }
    BlendFactor {
        Zero = GL_ZERO 0x0000,
        One = GL_ONE 0x0001,
        SrcColor = GL_SRC_COLOR 0x0300,
        OneMinusSrcColor = GL_ONE_MINUS_SRC_COLOR 0x0301,
        SrcAlpha = GL_SRC_ALPHA 0x0302,
        OneMinusSrcAlpha = GL_ONE_MINUS_SRC_ALPHA 0x0303,
        DstAlpha = GL_DST_ALPHA 0x0304,
        OneMinusDstAlpha = GL_ONE_MINUS_DST_ALPHA 0x0305,
        DstColor = GL_DST_COLOR 0x0306,
        OneMinusDstColor = GL_ONE_MINUS_DST_COLOR 0x0307,
        SrcAlphaSaturate = GL_SRC_ALPHA_SATURATE 0x0308,
        ConstantColor = GL_CONSTANT_COLOR 0x8001,
        OneMinusConstantColor = GL_ONE_MINUS_CONSTANT_COLOR 0x8002,
        ConstantAlpha = GL_CONSTANT_ALPHA 0x8003,
        OneMinusConstantAlpha = GL_ONE_MINUS_CONSTANT_ALPHA 0x8004,
    }
    BlendEquation {
        Add = GL_FUNC_ADD 0x8006,
        Min = GL_MIN 0x8007,
        Max = GL_MAX 0x8008,
        Subtract = GL_FUNC_SUBTRACT 0x800A,
        ReverseSubtract = GL_FUNC_REVERSE_SUBTRACT 0x800B,
    }
    LogicOp {
        Clear = GL_CLEAR 0x1500,
        And = GL_AND 0x1501,
        AndReverse = GL_AND_REVERSE 0x1502,
        Copy = GL_COPY 0x1503,
        AndInverted = GL_AND_INVERTED 0x1504,
        Noop = GL_NOOP 0x1505,
        Xor = GL_XOR 0x1506,
        Or = GL_OR 0x1507,
        Nor = GL_NOR 0x1508,
        Equiv = GL_EQUIV 0x1509,
        Invert = GL_INVERT 0x150A,
        OrReverse = GL_OR_REVERSE 0x150B,
        CopyInverted = GL_COPY_INVERTED 0x150C,
        OrInverted = GL_OR_INVERTED 0x150D,
        Nand = GL_NAND 0x150E,
        Set = GL_SET 0x150F,
    }
    Face {
        Front = GL_FRONT 0x0404,
        Back = GL_BACK 0x0405,
        FrontAndBack = GL_FRONT_AND_BACK 0x0408,
    }
    FrontFace {
        Cw = GL_CW 0x0900,
        Ccw = GL_CCW 0x0901,
    }
    PolygonMode {
        Point = GL_POINT 0x1B00,
        Line = GL_LINE 0x1B01,
        Fill = GL_FILL 0x1B02,
    }
    ShadeModel {
        Flat = GL_FLAT 0x1D00,
        Smooth = GL_SMOOTH 0x1D01,
    }
    MatrixMode {
        Modelview = GL_MODELVIEW 0x1700,
        Projection = GL_PROJECTION 0x1701,
        Texture = GL_TEXTURE 0x1702,
    }
    Capability {
        CullFace = GL_CULL_FACE 0x0B44,
        Fog = GL_FOG 0x0B60,
        DepthTest = GL_DEPTH_TEST 0x0B71,
        StencilTest = GL_STENCIL_TEST 0x0B90,
        AlphaTest = GL_ALPHA_TEST 0x0BC0,
        Dither = GL_DITHER 0x0BD0,
        Blend = GL_BLEND 0x0BE2,
        ColorLogicOp = GL_COLOR_LOGIC_OP 0x0BF2,
        ScissorTest = GL_SCISSOR_TEST 0x0C11,
        PolygonOffsetPoint = GL_POLYGON_OFFSET_POINT 0x2A01,
        PolygonOffsetLine = GL_POLYGON_OFFSET_LINE 0x2A02,
        PolygonOffsetFill = GL_POLYGON_OFFSET_FILL 0x8037,
        ColorSum = GL_COLOR_SUM 0x8458,
        LineStipple = GL_LINE_STIPPLE 0x0B24,
        PolygonStipple = GL_POLYGON_STIPPLE 0x0B42,
        Lighting = GL_LIGHTING 0x0B50,
        ColorMaterial = GL_COLOR_MATERIAL 0x0B57,
        Normalize = GL_NORMALIZE 0x0BA1,
        RescaleNormal = GL_RESCALE_NORMAL 0x803A,
        ClipPlane(0) = GL_CLIP_PLANE0 0x3000,
        ClipPlane(1) = GL_CLIP_PLANE1 0x3001,
        ClipPlane(2) = GL_CLIP_PLANE2 0x3002,
        ClipPlane(3) = GL_CLIP_PLANE3 0x3003,
        ClipPlane(4) = GL_CLIP_PLANE4 0x3004,
        ClipPlane(5) = GL_CLIP_PLANE5 0x3005,
        Light(0) = GL_LIGHT0 0x4000,
        Light(1) = GL_LIGHT1 0x4001,
        Light(2) = GL_LIGHT2 0x4002,
        Light(3) = GL_LIGHT3 0x4003,
        Light(4) = GL_LIGHT4 0x4004,
        Light(5) = GL_LIGHT5 0x4005,
        Light(6) = GL_LIGHT6 0x4006,
        Light(7) = GL_LIGHT7 0x4007,
        TexGen(TexCoordName::S) = GL_TEXTURE_GEN_S 0x0C60,
        TexGen(TexCoordName::T) = GL_TEXTURE_GEN_T 0x0C61,
        TexGen(TexCoordName::R) = GL_TEXTURE_GEN_R 0x0C62,
        TexGen(TexCoordName::Q) = GL_TEXTURE_GEN_Q 0x0C63,
        Multisample = GL_MULTISAMPLE 0x809D,
        SampleAlphaToCoverage = GL_SAMPLE_ALPHA_TO_COVERAGE 0x809E,
        SampleAlphaToOne = GL_SAMPLE_ALPHA_TO_ONE 0x809F,
        SampleCoverage = GL_SAMPLE_COVERAGE 0x80A0,
        Texture(TextureTarget::D1) = GL_TEXTURE_1D 0x0DE0,
        Texture(TextureTarget::D2) = GL_TEXTURE_2D 0x0DE1,
        Texture(TextureTarget::D3) = GL_TEXTURE_3D 0x806F,
        Texture(TextureTarget::Cube) = GL_TEXTURE_CUBE_MAP 0x8513,
        Texture(TextureTarget::Rect) = GL_TEXTURE_RECTANGLE_ARB 0x84F5,
    }
    ColorControl {
        SingleColor = GL_SINGLE_COLOR 0x81F9,
        SeparateSpecular = GL_SEPARATE_SPECULAR_COLOR 0x81FA,
    }
    ColorMaterialMode {
        Ambient = GL_AMBIENT 0x1200,
        Diffuse = GL_DIFFUSE 0x1201,
        Specular = GL_SPECULAR 0x1202,
        Emission = GL_EMISSION 0x1600,
        AmbientAndDiffuse = GL_AMBIENT_AND_DIFFUSE 0x1602,
    }
    LightParamName {
        Ambient = GL_AMBIENT 0x1200,
        Diffuse = GL_DIFFUSE 0x1201,
        Specular = GL_SPECULAR 0x1202,
        Position = GL_POSITION 0x1203,
        SpotDirection = GL_SPOT_DIRECTION 0x1204,
        SpotExponent = GL_SPOT_EXPONENT 0x1205,
        SpotCutoff = GL_SPOT_CUTOFF 0x1206,
        ConstantAttenuation = GL_CONSTANT_ATTENUATION 0x1207,
        LinearAttenuation = GL_LINEAR_ATTENUATION 0x1208,
        QuadraticAttenuation = GL_QUADRATIC_ATTENUATION 0x1209,
    }
    MaterialParamName {
        Ambient = GL_AMBIENT 0x1200,
        Diffuse = GL_DIFFUSE 0x1201,
        Specular = GL_SPECULAR 0x1202,
        Emission = GL_EMISSION 0x1600,
        Shininess = GL_SHININESS 0x1601,
    }
    FogMode {
        Exp = GL_EXP 0x0800,
        Exp2 = GL_EXP2 0x0801,
        Linear = GL_LINEAR 0x2601,
    }
    FogCoordSrc {
        FogCoord = GL_FOG_COORD 0x8451,
        FragmentDepth = GL_FRAGMENT_DEPTH 0x8452,
    }
    // Texture units (`crate::texture::unit`).
    TexCoordName {
        S = GL_S 0x2000,
        T = GL_T 0x2001,
        R = GL_R 0x2002,
        Q = GL_Q 0x2003,
    }
    TexGenMode {
        EyeLinear = GL_EYE_LINEAR 0x2400,
        ObjectLinear = GL_OBJECT_LINEAR 0x2401,
        SphereMap = GL_SPHERE_MAP 0x2402,
        NormalMap = GL_NORMAL_MAP 0x8511,
        ReflectionMap = GL_REFLECTION_MAP 0x8512,
    }
    EnvMode {
        Add = GL_ADD 0x0104,
        Blend = GL_BLEND 0x0BE2,
        Modulate = GL_MODULATE 0x2100,
        Decal = GL_DECAL 0x2101,
        Replace = GL_REPLACE 0x1E01,
        Combine = GL_COMBINE 0x8570,
    }
    CombineFn {
        Add = GL_ADD 0x0104,
        Replace = GL_REPLACE 0x1E01,
        Modulate = GL_MODULATE 0x2100,
        Subtract = GL_SUBTRACT 0x84E7,
        AddSigned = GL_ADD_SIGNED 0x8574,
        Interpolate = GL_INTERPOLATE 0x8575,
        Dot3Rgb = GL_DOT3_RGB 0x86AE,
        Dot3Rgba = GL_DOT3_RGBA 0x86AF,
    }
    CombineSrc {
        Texture = GL_TEXTURE 0x1702,
        TextureUnit(0) = GL_TEXTURE0 0x84C0,
        TextureUnit(1) = GL_TEXTURE1 0x84C1,
        TextureUnit(2) = GL_TEXTURE2 0x84C2,
        TextureUnit(3) = GL_TEXTURE3 0x84C3,
        TextureUnit(4) = GL_TEXTURE4 0x84C4,
        TextureUnit(5) = GL_TEXTURE5 0x84C5,
        TextureUnit(6) = GL_TEXTURE6 0x84C6,
        TextureUnit(7) = GL_TEXTURE7 0x84C7,
        Constant = GL_CONSTANT 0x8576,
        PrimaryColor = GL_PRIMARY_COLOR 0x8577,
        Previous = GL_PREVIOUS 0x8578,
    }
    Operand {
        SrcColor = GL_SRC_COLOR 0x0300,
        OneMinusSrcColor = GL_ONE_MINUS_SRC_COLOR 0x0301,
        SrcAlpha = GL_SRC_ALPHA 0x0302,
        OneMinusSrcAlpha = GL_ONE_MINUS_SRC_ALPHA 0x0303,
    }
}

// Textures (`texture/`).
use crate::texture::{
    DepthMode, Filter, InternalFormat, PixelFormat, PixelType, TexLevelParamName, TexParamName, TextureTarget, Wrap,
};

gl_enums! {
    TextureTarget {
        D1 = GL_TEXTURE_1D 0x0DE0,
        D2 = GL_TEXTURE_2D 0x0DE1,
        D3 = GL_TEXTURE_3D 0x806F,
        Cube = GL_TEXTURE_CUBE_MAP 0x8513,
        Rect = GL_TEXTURE_RECTANGLE_ARB 0x84F5,
    }
    Filter {
        Nearest = GL_NEAREST 0x2600,
        Linear = GL_LINEAR 0x2601,
    }
    Wrap {
        Clamp = GL_CLAMP 0x2900,
        Repeat = GL_REPEAT 0x2901,
        ClampToBorder = GL_CLAMP_TO_BORDER 0x812D,
        ClampToEdge = GL_CLAMP_TO_EDGE 0x812F,
        MirroredRepeat = GL_MIRRORED_REPEAT 0x8370,
    }
    DepthMode {
        Alpha = GL_ALPHA 0x1906,
        Luminance = GL_LUMINANCE 0x1909,
        Intensity = GL_INTENSITY 0x8049,
    }
    PixelFormat {
        DepthComponent = GL_DEPTH_COMPONENT 0x1902,
        Red = GL_RED 0x1903,
        Green = GL_GREEN 0x1904,
        Blue = GL_BLUE 0x1905,
        Alpha = GL_ALPHA 0x1906,
        Rgb = GL_RGB 0x1907,
        Rgba = GL_RGBA 0x1908,
        Luminance = GL_LUMINANCE 0x1909,
        LuminanceAlpha = GL_LUMINANCE_ALPHA 0x190A,
        Bgr = GL_BGR 0x80E0,
        Bgra = GL_BGRA 0x80E1,
        DepthStencil = GL_DEPTH_STENCIL 0x84F9,
    }
    PixelType {
        Byte = GL_BYTE 0x1400,
        UnsignedByte = GL_UNSIGNED_BYTE 0x1401,
        Short = GL_SHORT 0x1402,
        UnsignedShort = GL_UNSIGNED_SHORT 0x1403,
        Int = GL_INT 0x1404,
        UnsignedInt = GL_UNSIGNED_INT 0x1405,
        Float = GL_FLOAT 0x1406,
        UnsignedByte332 = GL_UNSIGNED_BYTE_3_3_2 0x8032,
        UnsignedShort4444 = GL_UNSIGNED_SHORT_4_4_4_4 0x8033,
        UnsignedShort5551 = GL_UNSIGNED_SHORT_5_5_5_1 0x8034,
        UnsignedInt8888 = GL_UNSIGNED_INT_8_8_8_8 0x8035,
        UnsignedInt1010102 = GL_UNSIGNED_INT_10_10_10_2 0x8036,
        UnsignedByte233Rev = GL_UNSIGNED_BYTE_2_3_3_REV 0x8362,
        UnsignedShort565 = GL_UNSIGNED_SHORT_5_6_5 0x8363,
        UnsignedShort565Rev = GL_UNSIGNED_SHORT_5_6_5_REV 0x8364,
        UnsignedShort4444Rev = GL_UNSIGNED_SHORT_4_4_4_4_REV 0x8365,
        UnsignedShort1555Rev = GL_UNSIGNED_SHORT_1_5_5_5_REV 0x8366,
        UnsignedInt8888Rev = GL_UNSIGNED_INT_8_8_8_8_REV 0x8367,
        UnsignedInt2101010Rev = GL_UNSIGNED_INT_2_10_10_10_REV 0x8368,
        UnsignedInt248 = GL_UNSIGNED_INT_24_8 0x84FA,
        Float32UnsignedInt248Rev = GL_FLOAT_32_UNSIGNED_INT_24_8_REV 0x8DAD,
    }
    InternalFormat {
        One = GL_1 0x0001,
        Two = GL_2 0x0002,
        Three = GL_3 0x0003,
        Four = GL_4 0x0004,
        DepthComponent = GL_DEPTH_COMPONENT 0x1902,
        Alpha = GL_ALPHA 0x1906,
        Rgb = GL_RGB 0x1907,
        Rgba = GL_RGBA 0x1908,
        Luminance = GL_LUMINANCE 0x1909,
        LuminanceAlpha = GL_LUMINANCE_ALPHA 0x190A,
        R3G3B2 = GL_R3_G3_B2 0x2A10,
        Alpha4 = GL_ALPHA4 0x803B,
        Alpha8 = GL_ALPHA8 0x803C,
        Alpha12 = GL_ALPHA12 0x803D,
        Alpha16 = GL_ALPHA16 0x803E,
        Luminance4 = GL_LUMINANCE4 0x803F,
        Luminance8 = GL_LUMINANCE8 0x8040,
        Luminance12 = GL_LUMINANCE12 0x8041,
        Luminance16 = GL_LUMINANCE16 0x8042,
        Luminance4Alpha4 = GL_LUMINANCE4_ALPHA4 0x8043,
        Luminance6Alpha2 = GL_LUMINANCE6_ALPHA2 0x8044,
        Luminance8Alpha8 = GL_LUMINANCE8_ALPHA8 0x8045,
        Luminance12Alpha4 = GL_LUMINANCE12_ALPHA4 0x8046,
        Luminance12Alpha12 = GL_LUMINANCE12_ALPHA12 0x8047,
        Luminance16Alpha16 = GL_LUMINANCE16_ALPHA16 0x8048,
        Intensity = GL_INTENSITY 0x8049,
        Intensity4 = GL_INTENSITY4 0x804A,
        Intensity8 = GL_INTENSITY8 0x804B,
        Intensity12 = GL_INTENSITY12 0x804C,
        Intensity16 = GL_INTENSITY16 0x804D,
        Rgb4 = GL_RGB4 0x804F,
        Rgb5 = GL_RGB5 0x8050,
        Rgb8 = GL_RGB8 0x8051,
        Rgb10 = GL_RGB10 0x8052,
        Rgb12 = GL_RGB12 0x8053,
        Rgb16 = GL_RGB16 0x8054,
        Rgba2 = GL_RGBA2 0x8055,
        Rgba4 = GL_RGBA4 0x8056,
        Rgb5A1 = GL_RGB5_A1 0x8057,
        Rgba8 = GL_RGBA8 0x8058,
        Rgb10A2 = GL_RGB10_A2 0x8059,
        Rgba12 = GL_RGBA12 0x805A,
        Rgba16 = GL_RGBA16 0x805B,
        DepthComponent16 = GL_DEPTH_COMPONENT16 0x81A5,
        DepthComponent24 = GL_DEPTH_COMPONENT24 0x81A6,
        DepthComponent32 = GL_DEPTH_COMPONENT32 0x81A7,
        CompressedAlpha = GL_COMPRESSED_ALPHA 0x84E9,
        CompressedLuminance = GL_COMPRESSED_LUMINANCE 0x84EA,
        CompressedLuminanceAlpha = GL_COMPRESSED_LUMINANCE_ALPHA 0x84EB,
        CompressedIntensity = GL_COMPRESSED_INTENSITY 0x84EC,
        CompressedRgb = GL_COMPRESSED_RGB 0x84ED,
        CompressedRgba = GL_COMPRESSED_RGBA 0x84EE,
        DepthStencil = GL_DEPTH_STENCIL 0x84F9,
        Depth24Stencil8 = GL_DEPTH24_STENCIL8 0x88F0,
        DepthComponent32F = GL_DEPTH_COMPONENT32F 0x8CAC,
        Depth32FStencil8 = GL_DEPTH32F_STENCIL8 0x8CAD,
        Srgb = GL_SRGB 0x8C40,
        Srgb8 = GL_SRGB8 0x8C41,
        SrgbAlpha = GL_SRGB_ALPHA 0x8C42,
        Srgb8Alpha8 = GL_SRGB8_ALPHA8 0x8C43,
        SluminanceAlpha = GL_SLUMINANCE_ALPHA 0x8C44,
        Sluminance8Alpha8 = GL_SLUMINANCE8_ALPHA8 0x8C45,
        Sluminance = GL_SLUMINANCE 0x8C46,
        Sluminance8 = GL_SLUMINANCE8 0x8C47,
    }
    TexParamName {
        BorderColor = GL_TEXTURE_BORDER_COLOR 0x1004,
        MagFilter = GL_TEXTURE_MAG_FILTER 0x2800,
        MinFilter = GL_TEXTURE_MIN_FILTER 0x2801,
        WrapS = GL_TEXTURE_WRAP_S 0x2802,
        WrapT = GL_TEXTURE_WRAP_T 0x2803,
        Priority = GL_TEXTURE_PRIORITY 0x8066,
        Resident = GL_TEXTURE_RESIDENT 0x8067,
        WrapR = GL_TEXTURE_WRAP_R 0x8072,
        MinLod = GL_TEXTURE_MIN_LOD 0x813A,
        MaxLod = GL_TEXTURE_MAX_LOD 0x813B,
        BaseLevel = GL_TEXTURE_BASE_LEVEL 0x813C,
        MaxLevel = GL_TEXTURE_MAX_LEVEL 0x813D,
        GenerateMipmap = GL_GENERATE_MIPMAP 0x8191,
        LodBias = GL_TEXTURE_LOD_BIAS 0x8501,
        DepthMode = GL_DEPTH_TEXTURE_MODE 0x884B,
        CompareMode = GL_TEXTURE_COMPARE_MODE 0x884C,
        CompareFunc = GL_TEXTURE_COMPARE_FUNC 0x884D,
    }
    TexLevelParamName {
        Width = GL_TEXTURE_WIDTH 0x1000,
        Height = GL_TEXTURE_HEIGHT 0x1001,
        InternalFormat = GL_TEXTURE_INTERNAL_FORMAT 0x1003,
        Border = GL_TEXTURE_BORDER 0x1005,
        RedSize = GL_TEXTURE_RED_SIZE 0x805C,
        GreenSize = GL_TEXTURE_GREEN_SIZE 0x805D,
        BlueSize = GL_TEXTURE_BLUE_SIZE 0x805E,
        AlphaSize = GL_TEXTURE_ALPHA_SIZE 0x805F,
        LuminanceSize = GL_TEXTURE_LUMINANCE_SIZE 0x8060,
        IntensitySize = GL_TEXTURE_INTENSITY_SIZE 0x8061,
        Depth = GL_TEXTURE_DEPTH 0x8071,
        Compressed = GL_TEXTURE_COMPRESSED 0x86A1,
        DepthSize = GL_TEXTURE_DEPTH_SIZE 0x884A,
        StencilSize = GL_TEXTURE_STENCIL_SIZE 0x88F1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every entry decodes to itself, encodes to its value, and has a name
    /// and a value of its own within its type.
    fn round_trip<T: GlEnum>() -> usize {
        for (i, &(v, name, value)) in T::TABLE.iter().enumerate() {
            assert_eq!(v.to_gl(), value, "{v:?}");
            assert_eq!(T::from_gl(value), Some(v), "{name}");
            assert_eq!(v.gl_name(), name, "{v:?}");
            assert!(name.starts_with("GL_"), "{name}");
            for &(w, other_name, other_value) in &T::TABLE[..i] {
                assert_ne!(w, v, "{v:?} listed twice");
                assert_ne!(other_name, name);
                assert_ne!(other_value, value);
            }
        }
        T::TABLE.len()
    }

    #[test]
    fn every_entry_round_trips() {
        let counts = [
            round_trip::<PrimitiveMode>(),
            round_trip::<CompareFunc>(),
            round_trip::<StencilOp>(),
            round_trip::<BlendFactor>(),
            round_trip::<BlendEquation>(),
            round_trip::<LogicOp>(),
            round_trip::<Face>(),
            round_trip::<FrontFace>(),
            round_trip::<PolygonMode>(),
            round_trip::<ShadeModel>(),
            round_trip::<MatrixMode>(),
            round_trip::<Capability>(),
            round_trip::<ColorControl>(),
            round_trip::<ColorMaterialMode>(),
            round_trip::<LightParamName>(),
            round_trip::<MaterialParamName>(),
            round_trip::<FogMode>(),
            round_trip::<FogCoordSrc>(),
            round_trip::<TexCoordName>(),
            round_trip::<TexGenMode>(),
            round_trip::<EnvMode>(),
            round_trip::<CombineFn>(),
            round_trip::<CombineSrc>(),
            round_trip::<Operand>(),
        ];
        // Every variant of each type (to_gl's exhaustive match already
        // refuses a table without one).
        assert_eq!(
            counts,
            [10, 8, 8, 15, 5, 16, 3, 2, 3, 2, 3, 46, 2, 5, 10, 5, 3, 2, 4, 5, 6, 8, 12, 4]
        );
    }

    #[test]
    fn the_all_lists_are_in_table_order_where_gl_orders_them() {
        let values = |all: &[u32]| all.windows(2).all(|w| w[0] < w[1]);
        assert!(values(&CompareFunc::ALL.map(CompareFunc::to_gl)));
        assert!(values(&LogicOp::ALL.map(LogicOp::to_gl)));
        assert_eq!(LogicOp::ALL.map(LogicOp::to_gl)[0], 0x1500);
        assert_eq!(PrimitiveMode::from_gl(0x000A), None);
        assert_eq!(CompareFunc::from_gl(0x0208), None);
        assert_eq!(Capability::from_gl(0x0B50), Some(Capability::Lighting));
        assert_eq!(Capability::from_gl(0x4008), None, "GL_LIGHT8 does not exist");
        assert_eq!(Capability::from_gl(0x3006), None, "GL_CLIP_PLANE6 does not exist");
    }

    #[test]
    fn texture_enums_round_trip() {
        let counts = [
            round_trip::<TextureTarget>(),
            round_trip::<Filter>(),
            round_trip::<Wrap>(),
            round_trip::<DepthMode>(),
            round_trip::<PixelFormat>(),
            round_trip::<PixelType>(),
            round_trip::<InternalFormat>(),
            round_trip::<TexParamName>(),
            round_trip::<TexLevelParamName>(),
        ];
        assert_eq!(counts, [5, 2, 5, 3, 12, 21, 64, 17, 14]);
    }
}
