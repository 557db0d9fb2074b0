//! The reference sampler (`docs/llvmpipe-facts.md` §16).

use super::{TexUnitKey, TextureRef};

/// The filtered RGBA of `tex` at texture coordinates `at` = (s, t, r, q) of
/// the fragment, with `quad` the coordinates at the top-left, top-right and
/// bottom-left pixels of its 2×2 quad (llvmpipe's frame: quads at even `px`
/// and even `row`), for λ. All coordinates are before projection: the
/// sampler divides s, t, r by q.
///
/// Placeholder until the reference sampler lands: opaque white.
pub fn sample(unit: &TexUnitKey, tex: &TextureRef<'_>, at: [f32; 4], quad: [[f32; 4]; 3]) -> [f32; 4] {
    let _ = (unit, tex, at, quad);
    [1.0; 4]
}
