//! The varying layout a draw carries: only what its state reads.

use softgl::geometry::varying::VaryingLayout;
use softgl::{ColorFormat, Context, DepthFormat, FragmentKey, FramebufferDesc};

fn context() -> Context {
    Context::new(FramebufferDesc::rgba8_d24s8(8, 8)).unwrap()
}

#[test]
fn an_unlit_unfogged_draw_carries_the_primary_colour_only() {
    let gl = context();
    let (key, layout) = gl.draw_plan();
    assert_eq!(
        layout,
        VaryingLayout {
            color: true,
            ..VaryingLayout::default()
        }
    );
    assert_eq!(layout.len(), 4);
    assert_eq!(
        (layout.secondary(), layout.fog(), layout.back_color()),
        (None, None, None)
    );
    // The key of GL's initial state is the plain colour write: no shading stage.
    assert_eq!(
        key,
        FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true).normalized()
    );
}

#[test]
fn a_draw_writing_no_colour_carries_no_varyings() {
    let mut gl = context();
    gl.color_mask(false, false, false, false).unwrap();
    let (_, layout) = gl.draw_plan();
    assert!(layout.is_empty());
}
