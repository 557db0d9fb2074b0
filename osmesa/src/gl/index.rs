//! Colour-index state an RGBA context keeps without effect (GL 1.5 §4.2.2,
//! §4.2.3): `glClearIndex` (`GL_INDEX_CLEAR_VALUE`) and `glIndexMask`
//! (`GL_INDEX_WRITEMASK`), both in `GL_COLOR_BUFFER_BIT` and compiled into
//! display lists. (`glIndexPointer` is with the other arrays, `gl::arrays`.)

use super::rec;

exports! {
    [] fn glClearIndex(c: f32) {
        rec(move |os, gl| {
            super::outside(gl)?;
            // Stored as an unsigned integer, as Mesa (`clear.c`: `(GLuint) c`).
            os.clear_index = c as u32 as f32;
            Ok(())
        })
    }
    [] fn glIndexMask(mask: u32) {
        rec(move |os, gl| {
            super::outside(gl)?;
            os.index_mask = mask;
            Ok(())
        })
    }
}
