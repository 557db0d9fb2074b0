//! The image pyramid `gluBuild2DMipmaps` uploads for `GL_UNSIGNED_BYTE`
//! texels, as GLU 9.0.2 builds it (`src/libutil/mipmap.c`): the size rounded
//! to a power of two by `nearestPower`, the image resampled to it by
//! `scale_internal_ubyte` (an area-weighted box in f32, truncated), then
//! halved level by level by `halveImage_ubyte` (2x2 average rounded up from
//! .5; a one-texel-wide image averages pairs, truncated). The scenes upload
//! these levels themselves, so every back end gets the same texels; GLU's own
//! path is tested by the OSMesa C clients. Checked 2026-11-23 against Debian's
//! libGLU 9.0.2 (`gluBuild2DMipmaps` on Mesa, then `glGetTexImage` of every
//! level): byte-identical for RGBA images of 200x90, 4096x1, 1x100, 37x13,
//! 100x60 and 3x5.

/// One level: width, height, texels (`components` bytes each, rows tight).
pub type Level = (usize, usize, Vec<u8>);

/// GLU's `nearestPower`: a power of two near `v` (the largest not above it,
/// or the next one up when `v`'s two top bits are set, as for 3).
pub fn nearest_power(mut v: usize) -> usize {
    let mut i = 1;
    loop {
        match v {
            0 | 1 => return i,
            3 => return i * 4,
            _ => {
                v >>= 1;
                i *= 2;
            }
        }
    }
}

/// Every level `gluBuild2DMipmaps(…, w, h, …, GL_UNSIGNED_BYTE, data)` uploads,
/// level 0 first (the proxy check in GLU's `closestFit` passes for sizes up
/// to 4096).
pub fn build_2d_mipmaps(components: usize, w: usize, h: usize, data: &[u8]) -> Vec<Level> {
    let (nw, nh) = (nearest_power(w), nearest_power(h));
    let mut level = if (w, h) == (nw, nh) {
        (w, h, data.to_vec())
    } else {
        (nw, nh, scale(components, (w, h), data, (nw, nh)))
    };
    let mut out = Vec::new();
    loop {
        let (lw, lh) = (level.0, level.1);
        let done = lw == 1 && lh == 1;
        let next = (!done).then(|| halve(components, lw, lh, &level.2));
        out.push(level);
        match next {
            Some(n) => level = n,
            None => return out,
        }
    }
}

/// `halveImage_ubyte`.
fn halve(c: usize, w: usize, h: usize, d: &[u8]) -> Level {
    let at = |x: usize, y: usize, k: usize| u32::from(d[(y * w + x) * c + k]);
    if w == 1 || h == 1 {
        // halve1Dimage_ubyte: pairs along the long side, truncated.
        let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
        let mut o = Vec::with_capacity(nw * nh * c);
        for i in 0..nw.max(nh) {
            for k in 0..c {
                let (a, b) = if h == 1 {
                    (at(2 * i, 0, k), at(2 * i + 1, 0, k))
                } else {
                    (at(0, 2 * i, k), at(0, 2 * i + 1, k))
                };
                o.push(((a + b) / 2) as u8);
            }
        }
        return (nw, nh, o);
    }
    let (nw, nh) = (w / 2, h / 2);
    let mut o = Vec::with_capacity(nw * nh * c);
    for y in 0..nh {
        for x in 0..nw {
            for k in 0..c {
                let s = at(2 * x, 2 * y, k)
                    + at(2 * x + 1, 2 * y, k)
                    + at(2 * x, 2 * y + 1, k)
                    + at(2 * x + 1, 2 * y + 1, k);
                o.push(((s + 2) / 4) as u8);
            }
        }
    }
    (nw, nh, o)
}

/// `scale_internal_ubyte` (its f32 arithmetic, in its order; the result
/// truncated as C's float-to-`GLubyte` conversion does).
fn scale(c: usize, (wi, hi): (usize, usize), d: &[u8], (wo, ho): (usize, usize)) -> Vec<u8> {
    if wi == wo * 2 && hi == ho * 2 {
        return halve(c, wi, hi, d).2;
    }
    // GLU reads one texel past a row's end with weight 0 where the box ends
    // exactly on the image's edge; so does this, as 0.
    let px = |x: usize, y: usize, k: usize| d.get((y * wi + x) * c + k).map_or(0.0, |&v| f32::from(v));
    let convy = hi as f32 / ho as f32;
    let convx = wi as f32 / wo as f32;
    let (convy_int, convx_int) = (convy.floor() as usize, convx.floor() as usize);
    let (convy_float, convx_float) = (convy - convy_int as f32, convx - convx_int as f32);
    let area = convx * convy;
    let mut out = vec![0u8; wo * ho * c];
    let (mut lowy_int, mut lowy_float, mut highy_int, mut highy_float) = (0usize, 0f32, convy_int, convy_float);
    for i in 0..ho {
        highy_int = highy_int.min(hi - 1);
        let (mut lowx_int, mut lowx_float, mut highx_int, mut highx_float) = (0usize, 0f32, convx_int, convx_float);
        for j in 0..wo {
            let mut totals = [0f32; 4];
            for (k, total) in totals.iter_mut().enumerate().take(c) {
                let mut t = 0f32;
                // One row of the box: its partial first and last texels and those between.
                let row = |t: &mut f32, y: usize, y_percent: f32| {
                    *t += px(lowx_int, y, k) * (y_percent * (1.0 - lowx_float));
                    for l in lowx_int + 1..highx_int {
                        *t += px(l, y, k) * y_percent;
                    }
                    *t += px(highx_int, y, k) * (y_percent * highx_float);
                };
                if highy_int > lowy_int && highx_int > lowx_int {
                    row(&mut t, lowy_int, 1.0 - lowy_float);
                    row(&mut t, highy_int, highy_float);
                    for m in lowy_int + 1..highy_int {
                        t += px(lowx_int, m, k) * (1.0 - lowx_float) + px(highx_int, m, k) * highx_float;
                    }
                } else if highy_int > lowy_int {
                    let x_percent = highx_float - lowx_float;
                    t += px(lowx_int, lowy_int, k) * ((1.0 - lowy_float) * x_percent);
                    for m in lowy_int + 1..highy_int {
                        t += px(lowx_int, m, k) * x_percent;
                    }
                    t += px(lowx_int, highy_int, k) * (x_percent * highy_float);
                } else if highx_int > lowx_int {
                    row(&mut t, lowy_int, highy_float - lowy_float);
                } else {
                    t += px(lowx_int, lowy_int, k) * ((highy_float - lowy_float) * (highx_float - lowx_float));
                }
                // The body.
                for m in lowy_int + 1..highy_int {
                    for l in lowx_int + 1..highx_int {
                        t += px(l, m, k);
                    }
                }
                *total = t;
            }
            for (k, total) in totals.iter().enumerate().take(c) {
                out[(j + i * wo) * c + k] = (total / area) as u8;
            }
            lowx_int = highx_int;
            lowx_float = highx_float;
            step(&mut highx_int, &mut highx_float, (convx_int, convx_float));
        }
        lowy_int = highy_int;
        lowy_float = highy_float;
        step(&mut highy_int, &mut highy_float, (convy_int, convy_float));
    }
    out
}

/// Moves a box edge kept as (whole, fraction) on by `by`, carrying the
/// fraction past 1 as GLU does (`> 1`, so an edge may sit at fraction 1).
fn step(int: &mut usize, frac: &mut f32, by: (usize, f32)) {
    *int += by.0;
    *frac += by.1;
    if *frac > 1.0 {
        *frac -= 1.0;
        *int += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_power_rounds_as_glu_does() {
        let got: Vec<_> = [1, 2, 3, 5, 6, 7, 60, 90, 96, 100, 200, 256]
            .map(nearest_power)
            .to_vec();
        assert_eq!(got, [1, 2, 4, 4, 8, 8, 64, 64, 128, 128, 256, 256]);
    }

    #[test]
    fn halving_rounds_squares_and_truncates_lines() {
        // 2x2 of one component: (1 + 2 + 3 + 5 + 2) / 4 = 3.
        assert_eq!(halve(1, 2, 2, &[1, 2, 3, 5]), (1, 1, vec![3]));
        // 2x1: (1 + 2) / 2 = 1.
        assert_eq!(halve(1, 2, 1, &[1, 2]), (1, 1, vec![1]));
        assert_eq!(halve(2, 1, 2, &[10, 0, 13, 255]), (1, 1, vec![11, 127]));
    }

    #[test]
    fn a_constant_image_stays_constant_through_the_pyramid() {
        // 200x90 -> 256x64 (x up, y down), then 9 levels to 1x1.
        let levels = build_2d_mipmaps(4, 200, 90, &[200u8, 100, 50, 255].repeat(200 * 90));
        let sizes: Vec<_> = levels.iter().map(|l| (l.0, l.1)).collect();
        assert_eq!(sizes[0], (256, 64));
        assert_eq!(*sizes.last().expect("levels"), (1, 1));
        assert_eq!(levels.len(), 9);
        for (w, h, d) in &levels {
            assert_eq!(d.len(), w * h * 4);
            // Area weights sum to the area up to f32 rounding: 1 LSB at most, truncated down.
            assert!(
                d.chunks(4)
                    .all(|p| (199..=200).contains(&p[0]) && (254..=255).contains(&p[3])),
                "{w}x{h}"
            );
        }
    }
}
