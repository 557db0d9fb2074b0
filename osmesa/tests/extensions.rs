//! `GL_EXTENSIONS` is honest: every function of every extension softgl
//! advertises resolves through `OSMesaGetProcAddress` and `eglGetProcAddress`
//! (MuJoCo loads each one it finds and crashes on a `NULL`), and `GL_VERSION`
//! starts with `major.minor`.
//!
//! The functions of each extension are listed here independently of the
//! library's own table (`osmesa/src/gl/extensions.rs`): taken from Mesa
//! 22.3.6's `src/mapi/glapi/gen/*.xml` (the `<category>` of each extension;
//! `GL_KHR_debug` without its GLES `KHR` names). An advertised extension
//! missing from this list fails the test: add it with its functions.

use std::ffi::{c_char, CStr};
use OSMesa::egl::eglGetProcAddress;
use OSMesa::*;

mod current;

/// Extensions softgl has or may come to advertise, with their entry points.
const KNOWN: &[(&str, &[&str])] = &[
    ("GL_ARB_clip_control", &["glClipControl"]),
    ("GL_ARB_depth_buffer_float", &[]),
    ("GL_ARB_depth_texture", &[]),
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
    ("GL_ARB_seamless_cube_map", &[]),
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
    ("GL_ARB_texture_rectangle", &[]),
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
            "glWindowPos2fARB",
            "glWindowPos2iARB",
            "glWindowPos2sARB",
            "glWindowPos2dvARB",
            "glWindowPos2fvARB",
            "glWindowPos2ivARB",
            "glWindowPos2svARB",
            "glWindowPos3dARB",
            "glWindowPos3fARB",
            "glWindowPos3iARB",
            "glWindowPos3sARB",
            "glWindowPos3dvARB",
            "glWindowPos3fvARB",
            "glWindowPos3ivARB",
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
    ("GL_EXT_shadow_funcs", &[]),
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
    ("GL_EXT_texture_rectangle", &[]),
    ("GL_EXT_texture_sRGB", &[]),
    (
        "GL_EXT_vertex_array",
        &[
            "glArrayElementEXT",
            "glColorPointerEXT",
            "glDrawArraysEXT",
            "glEdgeFlagPointerEXT",
            "glGetPointervEXT",
            "glIndexPointerEXT",
            "glNormalPointerEXT",
            "glTexCoordPointerEXT",
            "glVertexPointerEXT",
        ],
    ),
    (
        "GL_KHR_debug",
        &[
            "glDebugMessageControl",
            "glDebugMessageInsert",
            "glDebugMessageCallback",
            "glGetDebugMessageLog",
            "glPushDebugGroup",
            "glPopDebugGroup",
            "glObjectLabel",
            "glGetObjectLabel",
            "glObjectPtrLabel",
            "glGetObjectPtrLabel",
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
    ("GL_NV_texture_rectangle", &[]),
    ("GL_SGIS_generate_mipmap", &[]),
    ("GL_SGIS_texture_edge_clamp", &[]),
    ("GL_SGIS_texture_lod", &[]),
];

fn advertised() -> Vec<String> {
    let p = glGetString(0x1F03); // GL_EXTENSIONS
    assert!(!p.is_null());
    // SAFETY: glGetString returns a NUL-terminated string.
    let s = unsafe { CStr::from_ptr(p.cast::<c_char>()) }
        .to_str()
        .unwrap()
        .to_owned();
    assert!(s.ends_with(' '), "each name is followed by a space, as Mesa's");
    s.split_whitespace().map(str::to_owned).collect()
}

#[test]
fn every_function_of_every_advertised_extension_resolves() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current::current(&mut buf, 4, 4);
    let exts = advertised();
    assert!(exts.iter().any(|e| e == "GL_ARB_vertex_buffer_object"));
    let mut unresolved = Vec::new();
    for e in &exts {
        assert!(e.starts_with("GL_"), "{e}");
        assert_eq!(exts.iter().filter(|x| *x == e).count(), 1, "{e} is listed twice");
        let Some((_, fns)) = KNOWN.iter().find(|(name, _)| name == e) else {
            panic!("{e} is advertised but this test does not know its functions: add it to KNOWN");
        };
        for f in *fns {
            let c = std::ffi::CString::new(*f).unwrap();
            // SAFETY: NUL-terminated names.
            let (osmesa, egl) = unsafe { (OSMesaGetProcAddress(c.as_ptr()), eglGetProcAddress(c.as_ptr())) };
            if osmesa.is_none() || egl.is_none() {
                unresolved.push(format!("{e}: {f}"));
            }
        }
    }
    assert!(unresolved.is_empty(), "advertised but not resolved: {unresolved:#?}");
    OSMesaDestroyContext(ctx);
}

#[test]
fn the_version_starts_with_major_and_minor() {
    let mut buf = vec![0u8; 4 * 4 * 4];
    let ctx = current::current(&mut buf, 4, 4);
    let p = glGetString(0x1F02); // GL_VERSION
                                 // SAFETY: glGetString returns a NUL-terminated string.
    let v = unsafe { CStr::from_ptr(p.cast::<c_char>()) }.to_str().unwrap();
    let mut parts = v.split(|c: char| !c.is_ascii_digit());
    let (major, minor) = (parts.next().unwrap(), parts.next().unwrap());
    assert!(
        major.parse::<u32>().unwrap() >= 1 && minor.parse::<u32>().is_ok(),
        "{v}"
    );
    assert!(v.contains("softgl"), "{v}");
    OSMesaDestroyContext(ctx);
}
