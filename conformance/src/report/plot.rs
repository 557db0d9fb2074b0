//! The report's two plots: `error_vs_time.png` (one point per scene and
//! back end) and `backends.png` (one point per back end: total steady time
//! against median and worst error). Each back end has its own colour, from
//! the Okabe–Ito palette (told apart with any colour vision), and its own
//! marker; images identical to the reference sit on a labelled floor.

use super::ms;
use crate::backend::Outcome;
use crate::run::SceneResult;
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord, DrawingErrorKind};
use std::path::Path;

/// The system font the plots' labels use, if installed (Debian: fonts-dejavu-core).
const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Where an error of 0 (identical to the reference) is drawn on the log axis.
const FLOOR: f64 = 1e-4;

/// Okabe & Ito's colour-blind-safe palette, black first.
const OKABE_ITO: [RGBColor; 8] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 158, 115),
    RGBColor(213, 94, 0),
    RGBColor(0, 114, 178),
    RGBColor(204, 121, 167),
    RGBColor(240, 228, 66),
];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    Circle,
    Square,
    Triangle,
    Diamond,
    Cross,
    Star,
}

const SHAPES: [Shape; 6] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::Cross,
    Shape::Star,
];

/// A back end's colour and marker, by its place in the back-end list.
fn style(i: usize) -> (RGBColor, Shape) {
    (OKABE_ITO[i % OKABE_ITO.len()], SHAPES[i % SHAPES.len()])
}

/// A marker of `size` pixels at `at`, filled or drawn as an outline: one
/// element of its own (plotters' composed elements, made dynamic, would
/// need a `'static` drawing backend).
struct Marker<C> {
    at: C,
    shape: Shape,
    size: i32,
    color: RGBColor,
    filled: bool,
}

fn marker<C>(shape: Shape, at: C, size: i32, color: RGBColor, filled: bool) -> Marker<C> {
    Marker {
        at,
        shape,
        size,
        color,
        filled,
    }
}

impl<'a, C> PointCollection<'a, C> for &'a Marker<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for Marker<C> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = pos.next() else { return Ok(()) };
        let (s, fill) = (self.size, self.filled);
        let style = if fill {
            self.color.filled()
        } else {
            self.color.stroke_width(2)
        };
        let polygon = |backend: &mut DB, pts: Vec<BackendCoord>| {
            if fill {
                backend.fill_polygon(pts, &style)
            } else {
                let mut closed = pts.clone();
                closed.push(pts[0]);
                backend.draw_path(closed, &style)
            }
        };
        match self.shape {
            Shape::Circle => backend.draw_circle((x, y), s as u32, &style, fill),
            Shape::Square => backend.draw_rect((x - s, y - s), (x + s, y + s), &style, fill),
            Shape::Triangle => polygon(backend, vec![(x, y - s - 1), (x + s + 1, y + s), (x - s - 1, y + s)]),
            Shape::Diamond => polygon(
                backend,
                vec![(x, y - s - 1), (x + s + 1, y), (x, y + s + 1), (x - s - 1, y)],
            ),
            Shape::Cross | Shape::Star => {
                let line = self.color.stroke_width(2);
                backend.draw_line((x - s, y - s), (x + s, y + s), &line)?;
                backend.draw_line((x - s, y + s), (x + s, y - s), &line)?;
                if self.shape == Shape::Star {
                    backend.draw_line((x - s - 1, y), (x + s + 1, y), &line)?;
                    backend.draw_line((x, y - s - 1), (x, y + s + 1), &line)?;
                }
                Ok(())
            }
        }
    }
}

fn err(e: &dyn std::fmt::Display) -> String {
    e.to_string()
}

/// Registers the font; false (and a note) when it is not installed.
fn font() -> bool {
    let ok = match std::fs::read(FONT) {
        Ok(bytes) => {
            plotters::style::register_font("sans-serif", FontStyle::Normal, Box::leak(bytes.into_boxed_slice())).is_ok()
        }
        Err(_) => false,
    };
    if !ok {
        eprintln!("note: {FONT} not found (apt-get install -y fonts-dejavu-core); the plots have no labels");
    }
    ok
}

/// A (time ms, error) point for every scene a back end rendered and was compared on.
fn points(results: &[SceneResult], backend: &str) -> Vec<(f64, f64)> {
    results
        .iter()
        .filter_map(|s| {
            let r = s.get(backend)?;
            match (&r.outcome, r.metrics) {
                (Outcome::Rendered { timing, .. }, Some(m)) => Some((ms(timing.steady).max(1e-3), m.mae)),
                _ => None,
            }
        })
        .collect()
}

/// Log-axis range around `values` (at least one decade).
fn range(values: impl Iterator<Item = f64> + Clone, floor: f64) -> std::ops::Range<f64> {
    let lo = values.clone().fold(f64::INFINITY, f64::min).max(floor);
    let hi = values.fold(floor * 10.0, f64::max);
    let lo = if lo.is_finite() { lo } else { floor };
    lo / 2.0..hi * 2.0
}

/// The dashed floor where identical images are drawn, labelled.
fn draw_floor<'a, DB: DrawingBackend + 'a>(
    chart: &mut LogChart<'a, DB>,
    x: std::ops::Range<f64>,
    labels: bool,
) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let grey = RGBColor(120, 120, 120);
    let steps = 60;
    let ratio = (x.end / x.start).powf(1.0 / steps as f64);
    let xs: Vec<f64> = (0..=steps).map(|k| x.start * ratio.powi(k)).collect();
    chart
        .draw_series(
            xs.chunks(2)
                .filter(|c| c.len() == 2)
                .map(|c| PathElement::new(vec![(c[0], FLOOR), (c[1], FLOOR)], grey.stroke_width(1))),
        )
        .map_err(|e| err(&e))?;
    if labels {
        chart
            .draw_series(std::iter::once(Text::new(
                "identical to the reference (error 0)",
                (x.start * 1.1, FLOOR * 1.7),
                ("sans-serif", 15).into_font().color(&grey),
            )))
            .map_err(|e| err(&e))?;
    }
    Ok(())
}

/// A white chart with log axes (error up, time across), its mesh and the
/// labelled floor of identical images.
fn log_chart<'a, 'p>(
    root: &'a DrawingArea<BitMapBackend<'p>, Shift>,
    title: &str,
    x_desc: &str,
    (x, y): (std::ops::Range<f64>, std::ops::Range<f64>),
    labels: bool,
) -> Result<LogChart<'a, BitMapBackend<'p>>, String> {
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut b = ChartBuilder::on(root);
    b.margin(20);
    if labels {
        b.caption(title, ("sans-serif", 22))
            .x_label_area_size(45)
            .y_label_area_size(80);
    }
    let mut chart = b
        .build_cartesian_2d(x.clone().log_scale(), y.log_scale())
        .map_err(|e| err(&e))?;
    mesh(&mut chart, labels, x_desc, "mean abs. error per channel (log)")?;
    draw_floor(&mut chart, x, labels)?;
    Ok(chart)
}

/// `error_vs_time.png`: one point per scene and back end, error against the
/// scene's reference (log) over steady frame time (log).
pub fn error_vs_time(results: &[SceneResult], names: &[String], path: &Path) -> Result<(), String> {
    let labels = font();
    let all: Vec<(usize, f64, f64)> = names
        .iter()
        .enumerate()
        .flat_map(|(i, n)| points(results, n).into_iter().map(move |(t, e)| (i, t, e.max(FLOOR))))
        .collect();
    let x = range(all.iter().map(|p| p.1), 1e-3);
    let y = FLOOR / 3.0..range(all.iter().map(|p| p.2), FLOOR).end;
    let root = BitMapBackend::new(path, (1100, 750)).into_drawing_area();
    let mut chart = log_chart(
        &root,
        "error against the reference vs steady frame time, per scene",
        "steady frame time, ms (log)",
        (x, y),
        labels,
    )?;
    for (i, name) in names.iter().enumerate() {
        let (color, shape) = style(i);
        let filled = !name.ends_with("-warm");
        let series = chart
            .draw_series(
                all.iter()
                    .filter(|p| p.0 == i)
                    .map(|p| marker(shape, (p.1, p.2), 5, color, filled)),
            )
            .map_err(|e| err(&e))?;
        if labels {
            series
                .label(name.as_str())
                .legend(move |(x, y)| marker(shape, (x + 10, y), 5, color, filled));
        }
    }
    legend(&mut chart, labels, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(|e| err(&e))
}

/// Per back end: its total steady time, and the median and worst of its errors.
pub struct BackendPoint {
    pub name: String,
    pub scenes: usize,
    pub total_ms: f64,
    pub median: f64,
    pub worst: f64,
}

pub fn backend_points(results: &[SceneResult], names: &[String]) -> Vec<BackendPoint> {
    names
        .iter()
        .filter_map(|n| {
            let p = points(results, n);
            if p.is_empty() {
                return None;
            }
            let mut e: Vec<f64> = p.iter().map(|q| q.1).collect();
            e.sort_by(f64::total_cmp);
            Some(BackendPoint {
                name: n.clone(),
                scenes: p.len(),
                total_ms: p.iter().map(|q| q.0).sum(),
                median: e[e.len() / 2],
                worst: e[e.len() - 1],
            })
        })
        .collect()
}

/// `backends.png`: one column per back end at its total steady time, a
/// filled marker at its median error and an outline at its worst.
pub fn backends(results: &[SceneResult], names: &[String], path: &Path) -> Result<(), String> {
    let labels = font();
    let pts = backend_points(results, names);
    // Room on the right for the legend.
    let x = range(pts.iter().map(|p| p.total_ms), 1e-2);
    let x = x.start..x.end * 6.0;
    let y = FLOOR / 3.0..range(pts.iter().map(|p| p.worst.max(FLOOR)), FLOOR).end;
    let root = BitMapBackend::new(path, (1100, 650)).into_drawing_area();
    let mut chart = log_chart(
        &root,
        "per back end: total steady time vs median (filled) and worst (outline) error",
        "sum of steady frame times over the scenes rendered, ms (log)",
        (x, y),
        labels,
    )?;
    for p in &pts {
        let i = names.iter().position(|n| *n == p.name).unwrap_or(0);
        let (color, shape) = style(i);
        let (median, worst) = (p.median.max(FLOOR), p.worst.max(FLOOR));
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(p.total_ms, median), (p.total_ms, worst)],
                color.stroke_width(2),
            )))
            .map_err(|e| err(&e))?;
        chart
            .draw_series([marker(shape, (p.total_ms, worst), 7, color, false)])
            .map_err(|e| err(&e))?;
        let series = chart
            .draw_series([marker(shape, (p.total_ms, median), 7, color, true)])
            .map_err(|e| err(&e))?;
        if labels {
            series
                .label(format!("{} ({} scenes)", p.name, p.scenes))
                .legend(move |(x, y)| marker(shape, (x + 10, y), 6, color, true));
        }
    }
    legend(&mut chart, labels, SeriesLabelPosition::UpperRight)?;
    root.present().map_err(|e| err(&e))
}

type LogChart<'a, DB> = ChartContext<
    'a,
    DB,
    Cartesian2d<plotters::coord::combinators::LogCoord<f64>, plotters::coord::combinators::LogCoord<f64>>,
>;

fn mesh<'a, DB: DrawingBackend + 'a>(chart: &mut LogChart<'a, DB>, labels: bool, x: &str, y: &str) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let mut m = chart.configure_mesh();
    if labels {
        m.x_desc(x).y_desc(y);
    } else {
        m.disable_x_mesh().disable_y_mesh().x_labels(0).y_labels(0);
    }
    m.draw().map_err(|e| err(&e))
}

fn legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut LogChart<'a, DB>,
    labels: bool,
    at: SeriesLabelPosition,
) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    if labels {
        chart
            .configure_series_labels()
            .position(at)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 16))
            .draw()
            .map_err(|e| err(&e))?;
    }
    Ok(())
}
