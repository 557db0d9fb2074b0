//! Configs: RGBA8 and RGB8 (no alpha, as llvmpipe's XRGB configs), each
//! with depth 0/16/24 and stencil 0/8, single-sampled or with 4 samples a
//! pixel (`EGL_SAMPLE_BUFFERS` 1, as llvmpipe's: it has 1 and 4 samples
//! only, so a request for 2 gets 4), for pbuffers and desktop OpenGL;
//! `eglChooseConfig` with EGL 1.5's matching rules (§3.4.1, table 3.4) and
//! sort order (§3.4.1.2: a request that does not ask for alpha gets the
//! smaller RGB8 buffer first, as on Mesa), `eglGetConfigs`,
//! `eglGetConfigAttrib`.

use super::*;
use crate::consts::MAX_SIZE;

/// What varies between configs.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Config {
    /// `EGL_ALPHA_SIZE`: 8 (RGBA8), or 0 (RGB8).
    pub alpha: i32,
    pub depth: i32,
    pub stencil: i32,
    /// `EGL_SAMPLES`: 0, or 4 (`softgl::multisample::MAX_SAMPLES`).
    pub samples: i32,
}

/// The configs of one colour format and sample count, by depth then stencil.
const fn family(alpha: i32, samples: i32) -> [Config; 6] {
    const DEPTH_STENCIL: [(i32, i32); 6] = [(0, 0), (0, 8), (16, 0), (16, 8), (24, 0), (24, 8)];
    let mut out = [Config {
        alpha,
        depth: 0,
        stencil: 0,
        samples,
    }; 6];
    let mut i = 0;
    while i < 6 {
        (out[i].depth, out[i].stencil) = DEPTH_STENCIL[i];
        i += 1;
    }
    out
}

/// Every config; `EGL_CONFIG_ID` is the index + 1: RGBA8 (1–6), RGBA8 with
/// 4 samples (7–12), RGB8 (13–18), RGB8 with 4 samples (19–24).
pub(crate) const CONFIGS: [Config; 24] = {
    let families = [family(8, 0), family(8, 4), family(0, 0), family(0, 4)];
    let mut all = [family(8, 0)[0]; 24];
    let mut i = 0;
    while i < 24 {
        all[i] = families[i / 6][i % 6];
        i += 1;
    }
    all
};

pub(crate) fn config_handle(index: usize) -> EGLConfig {
    ((index + 1) << 4 | TAG_CONFIG) as EGLConfig
}

/// The index into [`CONFIGS`] of a config handle; `EGL_BAD_CONFIG` for another value.
pub(crate) fn config_index(config: EGLConfig) -> EglResult<usize> {
    let h = config as usize;
    let i = (h >> 4).wrapping_sub(1);
    if h & 0xF == TAG_CONFIG && i < CONFIGS.len() {
        Ok(i)
    } else {
        Err(EGL_BAD_CONFIG)
    }
}

/// The framebuffer of a `width` × `height` surface of config `index`.
pub(crate) fn framebuffer_desc(index: usize, width: u32, height: u32) -> softgl::FramebufferDesc {
    let c = CONFIGS[index];
    softgl::FramebufferDesc {
        width,
        height,
        color: if c.alpha > 0 {
            softgl::ColorFormat::Rgba8
        } else {
            softgl::ColorFormat::Rgb8
        },
        depth_bits: c.depth as u32,
        stencil_bits: c.stencil as u32,
    }
}

/// The samples a pixel of a surface of config `index` (1, or 4).
pub(crate) fn framebuffer_samples(index: usize) -> u32 {
    CONFIGS[index].samples.max(1) as u32
}

/// The value of `name` for config `index`, or `None` for a name that is not
/// a config attribute.
pub(crate) fn config_attrib(index: usize, name: EGLint) -> Option<EGLint> {
    let c = CONFIGS[index];
    Some(match name {
        EGL_BUFFER_SIZE => 24 + c.alpha,
        EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE => 8,
        EGL_ALPHA_SIZE => c.alpha,
        EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => 0,
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => EGL_FALSE as EGLint,
        EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
        EGL_CONFIG_CAVEAT => EGL_NONE,
        EGL_CONFIG_ID => index as EGLint + 1,
        EGL_CONFORMANT | EGL_RENDERABLE_TYPE => EGL_OPENGL_BIT,
        EGL_DEPTH_SIZE => c.depth,
        EGL_STENCIL_SIZE => c.stencil,
        EGL_LEVEL => 0,
        EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_HEIGHT => MAX_SIZE,
        EGL_MAX_PBUFFER_PIXELS => MAX_SIZE * MAX_SIZE,
        EGL_MAX_SWAP_INTERVAL | EGL_MIN_SWAP_INTERVAL => 0,
        EGL_NATIVE_RENDERABLE => EGL_FALSE as EGLint,
        EGL_NATIVE_VISUAL_ID => 0,
        EGL_NATIVE_VISUAL_TYPE => EGL_NONE,
        EGL_SAMPLES => c.samples,
        EGL_SAMPLE_BUFFERS => EGLint::from(c.samples > 0),
        EGL_SURFACE_TYPE => EGL_PBUFFER_BIT,
        EGL_TRANSPARENT_TYPE => EGL_NONE,
        EGL_TRANSPARENT_RED_VALUE | EGL_TRANSPARENT_GREEN_VALUE | EGL_TRANSPARENT_BLUE_VALUE => 0,
        _ => return None,
    })
}

/// How a requested value selects configs (EGL 1.5, table 3.4).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Rule {
    /// The config's value is at least the requested one.
    AtLeast,
    /// Equal.
    Exact,
    /// The config's value has every requested bit.
    Mask,
    /// Not used to select.
    Ignore,
}

/// Every attribute `eglChooseConfig` takes: its rule and default.
fn criterion(name: EGLint) -> Option<(Rule, EGLint)> {
    use Rule::*;
    Some(match name {
        EGL_BUFFER_SIZE | EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_LUMINANCE_SIZE | EGL_ALPHA_SIZE
        | EGL_ALPHA_MASK_SIZE | EGL_DEPTH_SIZE | EGL_SAMPLE_BUFFERS | EGL_SAMPLES | EGL_STENCIL_SIZE => (AtLeast, 0),
        EGL_BIND_TO_TEXTURE_RGB
        | EGL_BIND_TO_TEXTURE_RGBA
        | EGL_CONFIG_CAVEAT
        | EGL_CONFIG_ID
        | EGL_MAX_SWAP_INTERVAL
        | EGL_MIN_SWAP_INTERVAL
        | EGL_NATIVE_RENDERABLE
        | EGL_NATIVE_VISUAL_TYPE => (Exact, EGL_DONT_CARE),
        EGL_COLOR_BUFFER_TYPE => (Exact, EGL_RGB_BUFFER),
        EGL_LEVEL => (Exact, 0),
        EGL_TRANSPARENT_TYPE => (Exact, EGL_NONE),
        EGL_CONFORMANT => (Mask, 0),
        EGL_RENDERABLE_TYPE => (Mask, EGL_OPENGL_ES_BIT),
        EGL_SURFACE_TYPE => (Mask, EGL_WINDOW_BIT),
        // Transparent values count only for EGL_TRANSPARENT_RGB configs (there are none);
        // the pbuffer maxima and the visual id are ignored (§3.4.1).
        EGL_TRANSPARENT_RED_VALUE
        | EGL_TRANSPARENT_GREEN_VALUE
        | EGL_TRANSPARENT_BLUE_VALUE
        | EGL_MAX_PBUFFER_WIDTH
        | EGL_MAX_PBUFFER_HEIGHT
        | EGL_MAX_PBUFFER_PIXELS
        | EGL_NATIVE_VISUAL_ID
        | EGL_MATCH_NATIVE_PIXMAP => (Ignore, EGL_DONT_CARE),
        _ => return None,
    })
}

/// `EGL_BAD_ATTRIBUTE` for a value `name` cannot take.
fn check_value(name: EGLint, value: EGLint) -> EglResult<()> {
    let ok = match name {
        _ if value == EGL_DONT_CARE => name != EGL_LEVEL,
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA | EGL_NATIVE_RENDERABLE => {
            value == EGL_TRUE as EGLint || value == EGL_FALSE as EGLint
        }
        EGL_COLOR_BUFFER_TYPE => matches!(value, EGL_RGB_BUFFER | EGL_LUMINANCE_BUFFER),
        EGL_CONFIG_CAVEAT => matches!(value, EGL_NONE | EGL_SLOW_CONFIG | EGL_NON_CONFORMANT_CONFIG),
        EGL_TRANSPARENT_TYPE => matches!(value, EGL_NONE | EGL_TRANSPARENT_RGB),
        _ => match criterion(name) {
            Some((Rule::AtLeast, _)) => value >= 0,
            _ => true,
        },
    };
    if ok {
        Ok(())
    } else {
        Err(EGL_BAD_ATTRIBUTE)
    }
}

/// The configs `requested` selects, sorted as EGL sorts them.
pub(crate) fn choose(requested: &[(EGLint, EGLint)]) -> EglResult<Vec<usize>> {
    let mut wanted: Vec<(EGLint, Rule, EGLint)> = Vec::new();
    let mut native_pixmap = EGL_NONE;
    for &(name, value) in requested {
        let (rule, _) = criterion(name).ok_or(EGL_BAD_ATTRIBUTE)?;
        check_value(name, value)?;
        if name == EGL_MATCH_NATIVE_PIXMAP {
            native_pixmap = value;
        }
        // A later value of the same attribute wins.
        wanted.retain(|(n, _, _)| *n != name);
        wanted.push((name, rule, value));
    }
    if native_pixmap != EGL_NONE {
        // No native pixmap exists on a surfaceless display.
        return Err(EGL_BAD_NATIVE_PIXMAP);
    }
    let value = |name: EGLint| {
        wanted
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|&(_, _, v)| v)
            .or_else(|| criterion(name).map(|(_, d)| d))
            .unwrap_or(EGL_DONT_CARE)
    };
    let id = value(EGL_CONFIG_ID);
    if id != EGL_DONT_CARE {
        // Every other attribute is ignored.
        return Ok((0..CONFIGS.len()).filter(|&i| i as EGLint + 1 == id).collect());
    }
    // The defaults take part too (EGL_SURFACE_TYPE = EGL_WINDOW_BIT, …).
    let all_names = [
        EGL_BUFFER_SIZE,
        EGL_RED_SIZE,
        EGL_GREEN_SIZE,
        EGL_BLUE_SIZE,
        EGL_LUMINANCE_SIZE,
        EGL_ALPHA_SIZE,
        EGL_ALPHA_MASK_SIZE,
        EGL_DEPTH_SIZE,
        EGL_SAMPLE_BUFFERS,
        EGL_SAMPLES,
        EGL_STENCIL_SIZE,
        EGL_BIND_TO_TEXTURE_RGB,
        EGL_BIND_TO_TEXTURE_RGBA,
        EGL_CONFIG_CAVEAT,
        EGL_MAX_SWAP_INTERVAL,
        EGL_MIN_SWAP_INTERVAL,
        EGL_NATIVE_RENDERABLE,
        EGL_NATIVE_VISUAL_TYPE,
        EGL_COLOR_BUFFER_TYPE,
        EGL_LEVEL,
        EGL_TRANSPARENT_TYPE,
        EGL_CONFORMANT,
        EGL_RENDERABLE_TYPE,
        EGL_SURFACE_TYPE,
    ];
    let matches = |i: usize| {
        all_names.iter().all(|&name| {
            let want = value(name);
            let (rule, _) = criterion(name).expect("listed names are criteria");
            let have = config_attrib(i, name).expect("criteria are config attributes");
            want == EGL_DONT_CARE
                || match rule {
                    Rule::AtLeast => have >= want,
                    Rule::Exact => have == want,
                    Rule::Mask => have & want == want,
                    Rule::Ignore => true,
                }
        })
    };
    // §3.4.1.2: the colour bits of the components asked for (more first),
    // then smaller buffer size, sample buffers, samples, depth, stencil,
    // alpha mask, and the config id. (Caveat and buffer type are equal here.)
    let color_bits = |i: usize| -> EGLint {
        [
            EGL_RED_SIZE,
            EGL_GREEN_SIZE,
            EGL_BLUE_SIZE,
            EGL_ALPHA_SIZE,
            EGL_LUMINANCE_SIZE,
        ]
        .iter()
        .filter(|&&n| value(n) > 0)
        .map(|&n| config_attrib(i, n).unwrap_or(0))
        .sum()
    };
    let attr = |i: usize, n: EGLint| config_attrib(i, n).unwrap_or(0);
    let mut chosen: Vec<usize> = (0..CONFIGS.len()).filter(|&i| matches(i)).collect();
    chosen.sort_by_key(|&i| {
        (
            std::cmp::Reverse(color_bits(i)),
            attr(i, EGL_BUFFER_SIZE),
            attr(i, EGL_SAMPLE_BUFFERS),
            attr(i, EGL_SAMPLES),
            attr(i, EGL_DEPTH_SIZE),
            attr(i, EGL_STENCIL_SIZE),
            attr(i, EGL_ALPHA_MASK_SIZE),
            attr(i, EGL_CONFIG_ID),
        )
    });
    Ok(chosen)
}

/// The body of `eglGetConfigs` and `eglChooseConfig`: after the display
/// check, writes up to `size` handles of the configs `list` gives to
/// `configs` (when not `NULL`) and their number to `num_config`.
///
/// # Safety
/// `configs` is `NULL` or has room for `size` handles; `num_config` is `NULL` or writable.
unsafe fn hand_out(
    dpy: EGLDisplay,
    list: impl FnOnce() -> EglResult<Vec<usize>>,
    configs: *mut EGLConfig,
    size: EGLint,
    num_config: *mut EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        egl_state().check(dpy)?;
        let list = list()?;
        if num_config.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        let n = if configs.is_null() {
            list.len()
        } else {
            list.len().min(size.max(0) as usize)
        };
        if !configs.is_null() {
            for (k, &i) in list.iter().take(n).enumerate() {
                // SAFETY: k < size, and the caller's array has room for `size` handles.
                unsafe { *configs.add(k) = config_handle(i) };
            }
        }
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe { *num_config = n as EGLint };
        Ok(EGL_TRUE)
    })
}

/// `eglGetConfigs`: every config (or their number when `configs` is `NULL`).
///
/// # Safety
/// `configs` is `NULL` or has room for `config_size` handles; `num_config`
/// is `NULL` (`EGL_BAD_PARAMETER`) or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigs(
    dpy: EGLDisplay,
    configs: *mut EGLConfig,
    config_size: EGLint,
    num_config: *mut EGLint,
) -> EGLBoolean {
    let all = || Ok((0..CONFIGS.len()).collect());
    // SAFETY: the caller's contract.
    unsafe { hand_out(dpy, all, configs, config_size, num_config) }
}

/// `eglChooseConfig`: the configs matching `attrib_list`, best first.
/// `EGL_BAD_ATTRIBUTE` for an unknown attribute or a value it cannot take.
///
/// # Safety
/// `attrib_list` is `NULL` or ends with `EGL_NONE`; `configs` is `NULL` or
/// has room for `config_size` handles; `num_config` is `NULL` or writable.
#[no_mangle]
pub unsafe extern "C" fn eglChooseConfig(
    dpy: EGLDisplay,
    attrib_list: *const EGLint,
    configs: *mut EGLConfig,
    config_size: EGLint,
    num_config: *mut EGLint,
) -> EGLBoolean {
    // SAFETY: the caller's contract for the list.
    let chosen = || choose(&unsafe { int_attribs(attrib_list) }?);
    // SAFETY: the caller's contract for the outputs.
    unsafe { hand_out(dpy, chosen, configs, config_size, num_config) }
}

/// `eglGetConfigAttrib`.
///
/// # Safety
/// `value` is `NULL` (`EGL_BAD_PARAMETER`) or writable.
#[no_mangle]
pub unsafe extern "C" fn eglGetConfigAttrib(
    dpy: EGLDisplay,
    config: EGLConfig,
    attribute: EGLint,
    value: *mut EGLint,
) -> EGLBoolean {
    call(EGL_FALSE, || {
        egl_state().check(dpy)?;
        let i = config_index(config)?;
        let v = config_attrib(i, attribute).ok_or(EGL_BAD_ATTRIBUTE)?;
        if value.is_null() {
            return Err(EGL_BAD_PARAMETER);
        }
        // SAFETY: checked non-null; writable by the caller's contract.
        unsafe { *value = v };
        Ok(EGL_TRUE)
    })
}
