//! The varying layout a draw carries: only what its state reads.

use softgl::geometry::varying::VaryingLayout;
use softgl::{ColorFormat, Context, DepthFormat, FragmentKey, FramebufferDesc, ShadeKey};

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
    // The key of GL's initial state is the plain colour write, its shading
    // stage interpolating the primary colour alone: no colour sum, no fog.
    let plain = ShadeKey {
        color: true,
        ..ShadeKey::default()
    };
    let expected = FragmentKey {
        shade: Some(plain),
        ..FragmentKey::new(ColorFormat::Rgba8, Some(DepthFormat::D24), true).normalized()
    };
    assert_eq!(key, expected);
    assert_eq!((plain.color_sum, plain.fog, plain.flat), (false, None, false));
}

#[test]
fn a_draw_writing_no_colour_carries_no_varyings() {
    let mut gl = context();
    gl.color_mask(false, false, false, false).unwrap();
    let (_, layout) = gl.draw_plan();
    assert!(layout.is_empty());
}
