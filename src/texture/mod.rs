//! TEMPORARY stub until store's milestone (not to be committed).
pub mod texgen;
pub mod unit;
use softgl_jit::texture::{BaseFormat, SamplerKey, TexTarget, TextureRef};
#[derive(Default)]
pub struct TextureStore {
    _stub: (),
}
impl TextureStore {
    pub fn sampling(&self, _unit: usize, _t: TexTarget) -> Option<(SamplerKey, BaseFormat, TextureRef<'_>)> {
        None
    }
}
impl crate::context::Context {
    pub fn active_texture_unit(&self) -> usize {
        0
    }
}
