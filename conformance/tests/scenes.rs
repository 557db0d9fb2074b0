//! The scene list itself: enough scenes, unique names, deterministic calls.

use softgl::PrimitiveMode;
use softgl_conformance::call::Call;
use softgl_conformance::scenes::{self, Group};

#[test]
fn at_least_forty_scenes_with_unique_names_in_every_group() {
    let all = scenes::all();
    assert!(all.len() >= 40, "{} scenes", all.len());
    let mut names: Vec<_> = all.iter().map(|s| s.name).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), all.len(), "scene names repeat");
    for g in Group::ALL {
        assert!(all.iter().any(|s| s.group == g), "no scene in {g:?}");
    }
    for s in &all {
        assert!(!s.tolerance.reason.is_empty(), "{}: no reason", s.name);
    }
}

#[test]
fn recordings_are_deterministic() {
    for s in scenes::all() {
        // Debug text, because the NaN scene's calls are not `==` themselves.
        let text = |full| format!("{:?}", s.record(full).calls);
        assert_eq!(text(false), text(false), "{}", s.name);
        assert_eq!(text(true), text(true), "{}", s.name);
    }
}

#[test]
fn every_primitive_mode_is_drawn() {
    let all = scenes::all();
    for mode in PrimitiveMode::ALL {
        let used = all.iter().any(|s| s.record(false).calls.contains(&Call::Begin(mode)));
        assert!(used, "{mode:?} is drawn by no scene");
    }
}

#[test]
fn the_timing_scenes_draw_20k_triangles_at_1024() {
    let s = scenes::by_name("random_20k_depth").expect("scene exists");
    let rec = s.record(true);
    assert_eq!((rec.width, rec.height), (1024, 1024));
    let vertices = rec.calls.iter().filter(|c| matches!(c, Call::Vertex(_))).count();
    assert!(vertices >= 3 * 20_000, "{vertices} vertices");
}

#[test]
fn texture_scenes_make_no_gl_error_on_softgl() {
    use softgl::{Context, FramebufferDesc};
    use softgl_conformance::backend::softgl::replay;
    for s in scenes::all().into_iter().filter(|s| s.group == Group::Texture) {
        let rec = s.record(false);
        let mut gl = Context::new(FramebufferDesc::rgba8_d24s8(rec.width, rec.height)).expect("context");
        for (i, c) in rec.calls.iter().enumerate() {
            let r = replay(&mut gl, c);
            assert!(r.is_ok(), "{}: call {i} {c:?}: {r:?}", s.name);
        }
    }
}

#[test]
fn framebuffer_and_pixel_scenes_make_no_gl_error_on_softgl() {
    use softgl::FramebufferDesc;
    use softgl_conformance::backend::softgl::{context, Replayer};
    for s in scenes::all()
        .into_iter()
        .filter(|s| matches!(s.group, Group::Framebuffer | Group::Pixels))
    {
        let rec = s.record(false);
        let mut gl = context(FramebufferDesc::rgba8_d24s8(rec.width, rec.height), rec.accum).expect("context");
        let mut lists = Replayer::default();
        for (i, c) in rec.calls.iter().enumerate() {
            let r = lists.call(&mut gl, c);
            assert!(r.is_ok(), "{}: call {i} {c:?}: {r:?}", s.name);
        }
        assert_eq!(gl.get_error(), None, "{}", s.name);
    }
}
