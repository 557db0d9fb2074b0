//! How far an image lands from the reference.

use image::{Rgba, RgbaImage};

/// Distances of one image from the reference, over all four channels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Metrics {
    /// Largest difference of any channel of any pixel.
    pub max_diff: u8,
    /// Pixels with a channel differing by more than the scene's tolerance.
    pub over: usize,
    /// Pixels that differ, but by no more than the scene's tolerance
    /// (1..=channel; always 0 for a tolerance of 0).
    pub near: usize,
    /// `over` as a share of all pixels.
    pub share_over: f64,
    /// Mean absolute difference per channel.
    pub mae: f64,
    /// Peak signal-to-noise ratio in dB (infinite for identical images).
    pub psnr: f64,
    /// Pixels drawn (different from the background) in one image and not the other.
    pub coverage: usize,
    pub pixels: usize,
}

impl Metrics {
    pub fn identical(&self) -> bool {
        self.max_diff == 0
    }
}

/// Compares `test` with `reference`; `None` when their sizes differ.
pub fn compare(reference: &RgbaImage, test: &RgbaImage, background: [u8; 4], channel: u8) -> Option<Metrics> {
    if reference.dimensions() != test.dimensions() {
        return None;
    }
    let (mut max_diff, mut over, mut near, mut coverage) = (0u8, 0usize, 0usize, 0usize);
    let (mut abs, mut sq) = (0u64, 0u64);
    for (a, b) in reference.pixels().zip(test.pixels()) {
        let mut m = 0u8;
        for k in 0..4 {
            let d = a.0[k].abs_diff(b.0[k]);
            m = m.max(d);
            abs += d as u64;
            sq += d as u64 * d as u64;
        }
        max_diff = max_diff.max(m);
        over += (m > channel) as usize;
        near += (m > 0 && m <= channel) as usize;
        coverage += ((a.0 != background) != (b.0 != background)) as usize;
    }
    let pixels = (reference.width() * reference.height()) as usize;
    let values = (pixels * 4).max(1) as f64;
    let mse = sq as f64 / values;
    Some(Metrics {
        max_diff,
        over,
        near,
        share_over: over as f64 / pixels.max(1) as f64,
        mae: abs as f64 / values,
        psnr: if sq == 0 {
            f64::INFINITY
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
        coverage,
        pixels,
    })
}

/// Reference, test and their difference side by side (the difference
/// magnified 16 times, pixels over `channel` outlined in red), scaled up
/// so small scenes stay visible.
pub fn diff_image(reference: &RgbaImage, test: &RgbaImage, channel: u8) -> RgbaImage {
    let (w, h) = reference.dimensions();
    let zoom = (256 / w.max(h).max(1)).clamp(1, 8);
    let gap = 4;
    let mut out = RgbaImage::from_pixel(3 * w * zoom + 2 * gap, h * zoom, Rgba([40, 40, 40, 255]));
    let opaque = |p: &Rgba<u8>| Rgba([p.0[0], p.0[1], p.0[2], 255]);
    for y in 0..h {
        for x in 0..w {
            let a = reference.get_pixel(x, y);
            let b = test.get_pixel(x, y);
            let d: Vec<u8> = (0..4).map(|k| a.0[k].abs_diff(b.0[k])).collect();
            let m = *d.iter().max().expect("4 channels");
            let diff = if m > channel {
                Rgba([255, (m as u32 * 16).min(255) as u8, 0, 255])
            } else {
                let g = (m as u32 * 16).min(255) as u8;
                Rgba([g / 2, g, g, 255])
            };
            for (i, p) in [opaque(a), opaque(b), diff].into_iter().enumerate() {
                let ox = i as u32 * (w * zoom + gap);
                for dy in 0..zoom {
                    for dx in 0..zoom {
                        out.put_pixel(ox + x * zoom + dx, y * zoom + dy, p);
                    }
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metrics_of_a_known_difference() {
        let mut a = RgbaImage::from_pixel(4, 4, Rgba([0, 0, 0, 0]));
        a.put_pixel(3, 3, Rgba([0, 0, 0, 255]));
        let mut b = a.clone();
        b.put_pixel(1, 1, Rgba([10, 0, 0, 255]));
        b.put_pixel(2, 2, Rgba([0, 0, 0, 0]));
        b.put_pixel(3, 3, Rgba([0, 5, 0, 255]));
        let m = compare(&a, &b, [0; 4], 5).expect("same size");
        assert_eq!(m.max_diff, 255);
        assert_eq!(m.over, 1);
        assert_eq!(m.near, 1, "(3, 3) differs by 5, within the tolerance");
        assert_eq!(m.coverage, 1);
        assert_eq!(m.share_over, 1.0 / 16.0);
        assert!((m.mae - 270.0 / 64.0).abs() < 1e-12);
        let mse = (100.0 + 255.0 * 255.0 + 25.0) / 64.0;
        assert!((m.psnr - 10.0 * (65025.0f64 / mse).log10()).abs() < 1e-9);
        assert_eq!(compare(&a, &a, [0; 4], 0).expect("same size").psnr, f64::INFINITY);
        assert!(compare(&a, &RgbaImage::new(2, 2), [0; 4], 0).is_none());
    }
}
