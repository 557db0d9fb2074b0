//! `GL_VERSION` and `GL_EXTENSIONS`, from one table: each extension softgl
//! advertises with its entry points. `OSMesaGetProcAddress` (and
//! `eglGetProcAddress`) answers every one of them: by the export of that name,
//! or, for an `ARB`/`EXT` name softgl does not export, by the core function it
//! became (the same semantics, as GL's specification of the core version
//! says). `osmesa/tests/extensions.rs` walks the string and resolves them all.
//!
//! An extension belongs here only when all its functions and enumerants work.

use std::ffi::{CStr, CString};
use std::sync::OnceLock;

/// The version softgl reports; `GL_VERSION` starts with its digits
/// (clients parse it with `sscanf("%d.%d")`).
pub(crate) const VERSION: &CStr = c"1.5 softgl 0.1.0";

/// Every extension softgl advertises, with its entry points (GL's names,
/// from the extension's specification; Mesa's `src/mapi/glapi/gen`).
pub(crate) const EXTENSIONS: &[(&str, &[&str])] = &[
    (
        "GL_ARB_framebuffer_object",
        &[
            "glIsRenderbuffer",
            "glBindRenderbuffer",
            "glDeleteRenderbuffers",
            "glGenRenderbuffers",
            "glRenderbufferStorage",
            "glRenderbufferStorageMultisample",
            "glGetRenderbufferParameteriv",
            "glIsFramebuffer",
            "glBindFramebuffer",
            "glDeleteFramebuffers",
            "glGenFramebuffers",
            "glCheckFramebufferStatus",
            "glFramebufferTexture1D",
            "glFramebufferTexture2D",
            "glFramebufferTexture3D",
            "glFramebufferTextureLayer",
            "glFramebufferRenderbuffer",
            "glGetFramebufferAttachmentParameteriv",
            "glBlitFramebuffer",
            "glGenerateMipmap",
        ],
    ),
    ("GL_ARB_multisample", &["glSampleCoverageARB"]),
    (
        "GL_ARB_multitexture",
        &[
            "glActiveTextureARB",
            "glClientActiveTextureARB",
            "glMultiTexCoord1dARB",
            "glMultiTexCoord1dvARB",
            "glMultiTexCoord1fARB",
            "glMultiTexCoord1fvARB",
            "glMultiTexCoord1iARB",
            "glMultiTexCoord1ivARB",
            "glMultiTexCoord1sARB",
            "glMultiTexCoord1svARB",
            "glMultiTexCoord2dARB",
            "glMultiTexCoord2dvARB",
            "glMultiTexCoord2fARB",
            "glMultiTexCoord2fvARB",
            "glMultiTexCoord2iARB",
            "glMultiTexCoord2ivARB",
            "glMultiTexCoord2sARB",
            "glMultiTexCoord2svARB",
            "glMultiTexCoord3dARB",
            "glMultiTexCoord3dvARB",
            "glMultiTexCoord3fARB",
            "glMultiTexCoord3fvARB",
            "glMultiTexCoord3iARB",
            "glMultiTexCoord3ivARB",
            "glMultiTexCoord3sARB",
            "glMultiTexCoord3svARB",
            "glMultiTexCoord4dARB",
            "glMultiTexCoord4dvARB",
            "glMultiTexCoord4fARB",
            "glMultiTexCoord4fvARB",
            "glMultiTexCoord4iARB",
            "glMultiTexCoord4ivARB",
            "glMultiTexCoord4sARB",
            "glMultiTexCoord4svARB",
        ],
    ),
    ("GL_ARB_clip_control", &["glClipControl"]),
    ("GL_ARB_depth_buffer_float", &[]),
    ("GL_ARB_depth_texture", &[]),
    (
        "GL_ARB_occlusion_query",
        &[
            "glGenQueriesARB",
            "glDeleteQueriesARB",
            "glIsQueryARB",
            "glBeginQueryARB",
            "glEndQueryARB",
            "glGetQueryivARB",
            "glGetQueryObjectivARB",
            "glGetQueryObjectuivARB",
        ],
    ),
    (
        "GL_ARB_point_parameters",
        &["glPointParameterfARB", "glPointParameterfvARB"],
    ),
    ("GL_ARB_shadow", &[]),
    ("GL_ARB_texture_border_clamp", &[]),
    (
        "GL_ARB_texture_compression",
        &[
            "glCompressedTexImage3DARB",
            "glCompressedTexImage2DARB",
            "glCompressedTexImage1DARB",
            "glCompressedTexSubImage3DARB",
            "glCompressedTexSubImage2DARB",
            "glCompressedTexSubImage1DARB",
            "glGetCompressedTexImageARB",
        ],
    ),
    ("GL_ARB_texture_cube_map", &[]),
    ("GL_ARB_texture_env_add", &[]),
    ("GL_ARB_texture_env_combine", &[]),
    ("GL_ARB_texture_env_crossbar", &[]),
    ("GL_ARB_texture_env_dot3", &[]),
    ("GL_ARB_texture_mirrored_repeat", &[]),
    ("GL_ARB_texture_non_power_of_two", &[]),
    (
        "GL_ARB_transpose_matrix",
        &[
            "glLoadTransposeMatrixfARB",
            "glLoadTransposeMatrixdARB",
            "glMultTransposeMatrixfARB",
            "glMultTransposeMatrixdARB",
        ],
    ),
    (
        "GL_ARB_vertex_buffer_object",
        &[
            "glBindBufferARB",
            "glBufferDataARB",
            "glBufferSubDataARB",
            "glDeleteBuffersARB",
            "glGenBuffersARB",
            "glGetBufferParameterivARB",
            "glGetBufferPointervARB",
            "glGetBufferSubDataARB",
            "glIsBufferARB",
            "glMapBufferARB",
            "glUnmapBufferARB",
        ],
    ),
    (
        "GL_ARB_window_pos",
        &[
            "glWindowPos2dARB",
            "glWindowPos2dvARB",
            "glWindowPos2fARB",
            "glWindowPos2fvARB",
            "glWindowPos2iARB",
            "glWindowPos2ivARB",
            "glWindowPos2sARB",
            "glWindowPos2svARB",
            "glWindowPos3dARB",
            "glWindowPos3dvARB",
            "glWindowPos3fARB",
            "glWindowPos3fvARB",
            "glWindowPos3iARB",
            "glWindowPos3ivARB",
            "glWindowPos3sARB",
            "glWindowPos3svARB",
        ],
    ),
    ("GL_EXT_bgra", &[]),
    ("GL_EXT_blend_color", &["glBlendColorEXT"]),
    ("GL_EXT_blend_equation_separate", &["glBlendEquationSeparateEXT"]),
    ("GL_EXT_blend_func_separate", &["glBlendFuncSeparateEXT"]),
    ("GL_EXT_blend_minmax", &["glBlendEquationEXT"]),
    ("GL_EXT_blend_subtract", &[]),
    (
        "GL_EXT_copy_texture",
        &[
            "glCopyTexImage1DEXT",
            "glCopyTexImage2DEXT",
            "glCopyTexSubImage1DEXT",
            "glCopyTexSubImage2DEXT",
            "glCopyTexSubImage3DEXT",
        ],
    ),
    ("GL_EXT_draw_range_elements", &["glDrawRangeElementsEXT"]),
    ("GL_EXT_framebuffer_blit", &["glBlitFramebufferEXT"]),
    (
        "GL_EXT_framebuffer_multisample",
        &["glRenderbufferStorageMultisampleEXT"],
    ),
    (
        "GL_EXT_framebuffer_object",
        &[
            "glIsRenderbufferEXT",
            "glBindRenderbufferEXT",
            "glDeleteRenderbuffersEXT",
            "glGenRenderbuffersEXT",
            "glRenderbufferStorageEXT",
            "glGetRenderbufferParameterivEXT",
            "glIsFramebufferEXT",
            "glBindFramebufferEXT",
            "glDeleteFramebuffersEXT",
            "glGenFramebuffersEXT",
            "glCheckFramebufferStatusEXT",
            "glFramebufferTexture1DEXT",
            "glFramebufferTexture2DEXT",
            "glFramebufferTexture3DEXT",
            "glFramebufferRenderbufferEXT",
            "glGetFramebufferAttachmentParameterivEXT",
            "glGenerateMipmapEXT",
        ],
    ),
    (
        "GL_EXT_fog_coord",
        &[
            "glFogCoordfEXT",
            "glFogCoordfvEXT",
            "glFogCoorddEXT",
            "glFogCoorddvEXT",
            "glFogCoordPointerEXT",
        ],
    ),
    (
        "GL_EXT_multi_draw_arrays",
        &["glMultiDrawArraysEXT", "glMultiDrawElementsEXT"],
    ),
    ("GL_EXT_packed_depth_stencil", &[]),
    ("GL_EXT_packed_pixels", &[]),
    (
        "GL_EXT_point_parameters",
        &["glPointParameterfEXT", "glPointParameterfvEXT"],
    ),
    ("GL_EXT_rescale_normal", &[]),
    (
        "GL_EXT_secondary_color",
        &[
            "glSecondaryColor3bEXT",
            "glSecondaryColor3bvEXT",
            "glSecondaryColor3dEXT",
            "glSecondaryColor3dvEXT",
            "glSecondaryColor3fEXT",
            "glSecondaryColor3fvEXT",
            "glSecondaryColor3iEXT",
            "glSecondaryColor3ivEXT",
            "glSecondaryColor3sEXT",
            "glSecondaryColor3svEXT",
            "glSecondaryColor3ubEXT",
            "glSecondaryColor3ubvEXT",
            "glSecondaryColor3uiEXT",
            "glSecondaryColor3uivEXT",
            "glSecondaryColor3usEXT",
            "glSecondaryColor3usvEXT",
            "glSecondaryColorPointerEXT",
        ],
    ),
    ("GL_EXT_separate_specular_color", &[]),
    ("GL_EXT_stencil_wrap", &[]),
    ("GL_EXT_subtexture", &["glTexSubImage1DEXT", "glTexSubImage2DEXT"]),
    ("GL_EXT_texture3D", &["glTexImage3DEXT", "glTexSubImage3DEXT"]),
    ("GL_EXT_texture_cube_map", &[]),
    ("GL_EXT_texture_edge_clamp", &[]),
    ("GL_EXT_texture_env_add", &[]),
    ("GL_EXT_texture_env_combine", &[]),
    ("GL_EXT_texture_lod_bias", &[]),
    (
        "GL_EXT_texture_object",
        &[
            "glAreTexturesResidentEXT",
            "glBindTextureEXT",
            "glDeleteTexturesEXT",
            "glGenTexturesEXT",
            "glIsTextureEXT",
            "glPrioritizeTexturesEXT",
        ],
    ),
    (
        "GL_MESA_window_pos",
        &[
            "glWindowPos2dMESA",
            "glWindowPos2dvMESA",
            "glWindowPos2fMESA",
            "glWindowPos2fvMESA",
            "glWindowPos2iMESA",
            "glWindowPos2ivMESA",
            "glWindowPos2sMESA",
            "glWindowPos2svMESA",
            "glWindowPos3dMESA",
            "glWindowPos3dvMESA",
            "glWindowPos3fMESA",
            "glWindowPos3fvMESA",
            "glWindowPos3iMESA",
            "glWindowPos3ivMESA",
            "glWindowPos3sMESA",
            "glWindowPos3svMESA",
            "glWindowPos4dMESA",
            "glWindowPos4dvMESA",
            "glWindowPos4fMESA",
            "glWindowPos4fvMESA",
            "glWindowPos4iMESA",
            "glWindowPos4ivMESA",
            "glWindowPos4sMESA",
            "glWindowPos4svMESA",
        ],
    ),
    ("GL_NV_blend_square", &[]),
    ("GL_SGIS_generate_mipmap", &[]),
    ("GL_SGIS_texture_edge_clamp", &[]),
    ("GL_SGIS_texture_lod", &[]),
];

/// `GL_EXTENSIONS`: the table's names, each followed by a space, the last
/// one too, as Mesa's (docs/llvmpipe-facts.md §13).
pub(crate) fn extensions_string() -> &'static CStr {
    static S: OnceLock<CString> = OnceLock::new();
    S.get_or_init(|| {
        let s: String = EXTENSIONS.iter().map(|(name, _)| format!("{name} ")).collect();
        CString::new(s).unwrap_or_default()
    })
}

/// The core function that answers `name`, an advertised extension's entry
/// point with an `ARB` or `EXT` suffix; `None` for any other name.
pub(crate) fn core_name(name: &str) -> Option<&str> {
    let listed = EXTENSIONS.iter().any(|(_, fns)| fns.contains(&name));
    listed.then(|| name.strip_suffix("ARB").or_else(|| name.strip_suffix("EXT")))?
}
