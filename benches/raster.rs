//! Coverage of one 64x64 tile: the block rasterizer (`Edges::window` +
//! `tile_coverage`, a mask) against the row rasterizer it replaced
//! (`row_coverage` of the same snapped points, a mask), and the render
//! path's whole triangle (`triangle` with the tile as bounds, into a sink
//! that drops the spans; it also sets up the 1/w plane), on (a) a triangle covering the whole
//! tile, (b) random ~2000-pixel triangles and (c) random ~20-pixel triangles
//! centred in the tile. Throughput is in covered pixels; time per
//! tile-triangle is the time of an iteration over the triangle count.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use softgl::framebuffer::Rect;
use softgl::geometry::varying::{VaryingLayout, MAX_VARYINGS};
use softgl::raster::{row_coverage, tile_coverage, triangle, Edges, RasterParams, RasterVertex, SpanSink};
use softgl_jit::shade::Planes;
use softgl_jit::FragmentSpan;

const HEIGHT: u32 = 256;
const TILE: Rect = Rect {
    x0: 64,
    y0: 64,
    x1: 128,
    y1: 128,
};

/// Drops spans; gives the rasterizer planes to write, as the renderer's sink does.
struct Null(Box<Planes>);

impl SpanSink for Null {
    fn span(&mut self, span: &FragmentSpan) {
        black_box(span.mask);
    }
    fn planes_mut(&mut self) -> Option<&mut Planes> {
        Some(&mut self.0)
    }
}

fn vertex(x: f32, y: f32) -> RasterVertex {
    RasterVertex {
        x,
        y,
        y_down: HEIGHT as f32 - y,
        z: 0.5,
        inv_w: 1.0,
        v: [0.0; MAX_VARYINGS],
    }
}

/// `n` seeded random triangles of `area` pixels (random shapes, not too
/// thin), centred at random points of the tile.
fn random(n: usize, area: f32, seed: u32) -> Vec<[RasterVertex; 3]> {
    let mut rng = softgl::rng::Rng::new(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let p = [0; 3].map(|_| (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)));
        let a = ((p[1].0 - p[0].0) * (p[2].1 - p[0].1) - (p[2].0 - p[0].0) * (p[1].1 - p[0].1)).abs() / 2.0;
        if a < 0.1 {
            continue;
        }
        let s = (area / a).sqrt();
        let (cx, cy) = (rng.range(64.0, 128.0), rng.range(64.0, 128.0));
        let m = ((p[0].0 + p[1].0 + p[2].0) / 3.0, (p[0].1 + p[1].1 + p[2].1) / 3.0);
        out.push(p.map(|(x, y)| vertex(cx + (x - m.0) * s, cy + (y - m.1) * s)));
    }
    out
}

fn bench(c: &mut Criterion) {
    let params = RasterParams {
        bounds: TILE,
        depth: None,
        height: HEIGHT,
        layout: VaryingLayout::default(),
        offset: None,
    };
    let sets = [
        (
            "full_tile",
            vec![[vertex(-500.0, -500.0), vertex(2000.0, -500.0), vertex(-500.0, 2000.0)]],
        ),
        ("2000px", random(256, 2000.0, 1)),
        ("20px", random(1024, 20.0, 2)),
    ];
    let mut group = c.benchmark_group("tile_coverage");
    for (name, tris) in &sets {
        let edges: Vec<Option<Edges>> = tris
            .iter()
            .map(|t| Edges::window([&t[0], &t[1], &t[2]], HEIGHT))
            .collect();
        let pixels: u64 = edges
            .iter()
            .flatten()
            .map(|e| u64::from(tile_coverage(e, TILE, TILE).count()))
            .sum();
        let area: f32 = tris
            .iter()
            .map(|t| ((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y)).abs() / 2.0)
            .sum::<f32>()
            / tris.len() as f32;
        eprintln!(
            "{name}: {} triangles, mean area {area:.0} px, {pixels} covered pixels in the tile ({:.0} per triangle)",
            tris.len(),
            pixels as f64 / tris.len() as f64
        );
        group.throughput(Throughput::Elements(pixels));
        group.bench_function(format!("{name}/block"), |b| {
            b.iter(|| {
                for t in tris {
                    if let Some(e) = Edges::window([&t[0], &t[1], &t[2]], HEIGHT) {
                        black_box(tile_coverage(&e, TILE, TILE));
                    }
                }
            })
        });
        group.bench_function(format!("{name}/rows"), |b| {
            b.iter(|| {
                for t in tris {
                    let p = Edges::window_points([&t[0], &t[1], &t[2]], HEIGHT);
                    black_box(row_coverage(p, TILE, TILE));
                }
            })
        });
        let mut sink = Null(Box::default());
        group.bench_function(format!("{name}/triangle"), |b| {
            b.iter(|| {
                for t in tris {
                    triangle([&t[0], &t[1], &t[2]], None, &params, &mut sink);
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
