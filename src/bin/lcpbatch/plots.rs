//! SVG plots of `lcpbatch bench` and `lcpbatch stress` (plotters), shared.

use std::path::Path;

use lcpbatch::Error;
use plotters::prelude::*;

/// Colours of successive series.
pub const COLORS: [RGBColor; 8] = [
    RED,
    BLUE,
    GREEN,
    MAGENTA,
    CYAN,
    BLACK,
    RGBColor(255, 140, 0),
    RGBColor(128, 0, 128),
];

fn plot_error(path: &Path) -> impl Fn(String) -> Error + '_ {
    move |e| Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    }
}

/// Log-scale bounds with a margin of a factor 2 on each side.
fn bounds(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v
        .filter(|x| x.is_finite() && *x > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    if !lo.is_finite() || hi <= 0.0 {
        return (1e-3, 1.0);
    }
    (lo / 2.0, (hi * 2.0).max(lo))
}

/// A labelled scatter on log–log axes: one point per (x, y, label), with
/// the label written beside it when `labels`, else in a legend by label.
pub fn scatter(
    points: &[(f64, f64, String)],
    path: &Path,
    title: &str,
    (x_desc, y_desc): (&str, &str),
    labels: bool,
) -> Result<(), Error> {
    let err = plot_error(path);
    let (xmin, xmax) = bounds(points.iter().map(|p| p.0));
    let (ymin, ymax) = bounds(points.iter().map(|p| p.1));
    let root = SVGBackend::new(path, (1100, 750)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((xmin..xmax).log_scale(), (ymin..ymax).log_scale())
        .map_err(|e| err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| err(e.to_string()))?;
    let mut series: Vec<&str> = Vec::new();
    for p in points {
        if !series.contains(&p.2.as_str()) {
            series.push(&p.2);
        }
    }
    for (i, name) in series.iter().enumerate() {
        let c = COLORS[i % COLORS.len()];
        let pts = points.iter().filter(|p| p.2 == *name);
        let drawn = chart
            .draw_series(pts.clone().map(|p| Circle::new((p.0, p.1), 3, c.filled())))
            .map_err(|e| err(e.to_string()))?;
        if labels {
            for p in pts {
                chart
                    .draw_series(std::iter::once(Text::new(
                        p.2.clone(),
                        (p.0, p.1),
                        ("sans-serif", 10).into_font().color(&c),
                    )))
                    .map_err(|e| err(e.to_string()))?;
            }
        } else {
            drawn
                .label(name.to_string())
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
        }
    }
    if !labels {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(e.to_string()))?;
    }
    root.present().map_err(|e| err(e.to_string()))
}

/// One curve of a line plot: a label and (x, seconds-per-island) points.
pub type Curve = (String, Vec<(f64, f64)>);

/// Microseconds per island against `x_desc` (n or batch size): log y, and
/// log x when `log_x`.
pub fn curves(
    curves: &[Curve],
    path: &Path,
    title: &str,
    x_desc: &str,
    log_x: bool,
) -> Result<(), Error> {
    let err = plot_error(path);
    let xs = curves.iter().flat_map(|c| c.1.iter().map(|p| p.0));
    let (xlo, xhi) = xs
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    let (xmin, xmax) = bounds(xs);
    let (ymin, ymax) = bounds(curves.iter().flat_map(|c| c.1.iter().map(|p| p.1 * 1e6)));
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    // The two x axes have different types; the drawing is the same.
    macro_rules! draw {
        ($xr:expr) => {{
            let mut chart = ChartBuilder::on(&root)
                .caption(title, ("sans-serif", 20))
                .margin(15)
                .x_label_area_size(45)
                .y_label_area_size(70)
                .build_cartesian_2d($xr, (ymin..ymax).log_scale())
                .map_err(|e| err(e.to_string()))?;
            chart
                .configure_mesh()
                .x_desc(x_desc)
                .y_desc("microseconds per island")
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()
                .map_err(|e| err(e.to_string()))?;
            for (i, (label, pts)) in curves.iter().enumerate() {
                let c = COLORS[i % COLORS.len()];
                chart
                    .draw_series(LineSeries::new(
                        pts.iter().map(|&(x, y)| (x, y * 1e6)),
                        c.stroke_width(2),
                    ))
                    .map_err(|e| err(e.to_string()))?
                    .label(label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| err(e.to_string()))?;
        }};
    }
    if log_x {
        draw!((xmin..xmax).log_scale());
    } else {
        draw!((xlo - 0.5)..(xhi + 0.5));
    }
    root.present().map_err(|e| err(e.to_string()))
}

/// One panel of [`time_panels`]: lines against simulated time.
pub struct Panel {
    /// The y axis' name (with its unit).
    pub y_desc: String,
    /// The lines.
    pub series: Vec<Curve>,
    /// A log y axis with this floor and its name: values below it (zeros,
    /// rounding noise) are drawn on it, and it is marked. None: linear.
    pub floor: Option<(f64, String)>,
    /// Horizontal reference lines (name, y, colour), dashed.
    pub marks: Vec<(String, f64, RGBColor)>,
}

/// Panels stacked under a title of a line or more, sharing the time axis,
/// each with its legend to the right of its data.
pub fn time_panels(path: &Path, title: &[String], panels: &[Panel]) -> Result<(), Error> {
    let err = plot_error(path);
    let head = 20 + 20 * title.len() as u32;
    let root = SVGBackend::new(path, (1000, head + 300 * panels.len() as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let (top, body) = root.split_vertically(head);
    for (k, line) in title.iter().enumerate() {
        let size = if k == 0 { 18 } else { 14 };
        top.draw(&Text::new(
            line.clone(),
            (12, 8 + 20 * k as i32),
            ("sans-serif", size).into_font(),
        ))
        .map_err(|e| err(e.to_string()))?;
    }
    let time = |p: &Panel| {
        p.series
            .iter()
            .flat_map(|c| c.1.iter().map(|q| q.0))
            .collect::<Vec<_>>()
    };
    let (x0, x1) = panels
        .iter()
        .flat_map(time)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    let (x0, x1) = if x0 <= x1 {
        (x0, x1.max(x0 + 1e-9))
    } else {
        (0.0, 1.0)
    };
    for (panel, area) in panels.iter().zip(body.split_evenly((panels.len(), 1))) {
        let (plot, legend) = area.split_horizontally(760);
        let ys = || panel.series.iter().flat_map(|c| c.1.iter().map(|q| q.1));
        let mut keys: Vec<(String, ShapeStyle, bool)> = Vec::new();
        macro_rules! draw {
            ($yr:expr, $clamp:expr, $fmt:expr) => {{
                let mut chart = ChartBuilder::on(&plot)
                    .margin(10)
                    .x_label_area_size(40)
                    .y_label_area_size(80)
                    .build_cartesian_2d(x0..x1, $yr)
                    .map_err(|e| err(e.to_string()))?;
                chart
                    .configure_mesh()
                    .x_desc("simulated time (s)")
                    .y_desc(panel.y_desc.as_str())
                    .light_line_style(RGBColor(245, 245, 245))
                    .y_label_formatter(&$fmt)
                    .draw()
                    .map_err(|e| err(e.to_string()))?;
                let flat = |y: f64, style: ShapeStyle| {
                    DashedLineSeries::new([(x0, y), (x1, y)], 8, 5, style)
                };
                for (k, (name, pts)) in panel.series.iter().enumerate() {
                    let style = COLORS[k % COLORS.len()].stroke_width(2);
                    let clamp = $clamp;
                    chart
                        .draw_series(LineSeries::new(
                            pts.iter().map(|&(t, y)| (t, clamp(y))),
                            style,
                        ))
                        .map_err(|e| err(e.to_string()))?;
                    keys.push((name.clone(), style, false));
                }
                for (name, y, color) in &panel.marks {
                    let style = color.stroke_width(2);
                    chart
                        .draw_series(flat(*y, style))
                        .map_err(|e| err(e.to_string()))?;
                    keys.push((name.clone(), style, true));
                }
                // Over the lines that lie on it.
                if let Some((floor, name)) = &panel.floor {
                    let style = RGBColor(120, 120, 120).stroke_width(2);
                    chart
                        .draw_series(flat(*floor, style))
                        .map_err(|e| err(e.to_string()))?;
                    keys.push((name.clone(), style, true));
                }
            }};
        }
        match &panel.floor {
            Some((floor, _)) => {
                let marks = panel.marks.iter().map(|m| m.1);
                // Values at the floor are drawn on it: clamp, then the line over them.
                let hi = ys()
                    .chain(marks)
                    .filter(|y| y.is_finite())
                    .fold(*floor, f64::max);
                let clamp = |y: f64| if y.is_nan() { y } else { y.max(*floor) };
                draw!(
                    ((floor / 5.0)..(hi * 5.0)).log_scale(),
                    clamp,
                    |v: &f64| format!("{v:.0e}")
                );
            }
            None => {
                let (lo, hi) = ys()
                    .filter(|y| y.is_finite())
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
                        (a.min(y), b.max(y))
                    });
                let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 1.0) };
                // Rounding in a flat line stays flat: at least 0.1% of it.
                let pad = ((hi - lo) * 0.05)
                    .max(1e-3 * lo.abs().max(hi.abs()))
                    .max(1e-30);
                // One notation for the whole axis, by its largest value.
                let plain = (1e-2..1e5).contains(&lo.abs().max(hi.abs()));
                draw!((lo - pad)..(hi + pad), |y: f64| y, |v: &f64| {
                    if plain {
                        format!("{v:.3}")
                    } else {
                        format!("{v:.3e}")
                    }
                });
            }
        }
        for (k, (name, style, dashed)) in keys.iter().enumerate() {
            let y = 25 + 22 * k as i32;
            let dashes: &[(i32, i32)] = if *dashed {
                &[(8, 18), (26, 36)]
            } else {
                &[(8, 36)]
            };
            for &(a, b) in dashes {
                legend
                    .draw(&PathElement::new(vec![(a, y), (b, y)], *style))
                    .map_err(|e| err(e.to_string()))?;
            }
            legend
                .draw(&Text::new(
                    name.clone(),
                    (44, y - 7),
                    ("sans-serif", 13).into_font(),
                ))
                .map_err(|e| err(e.to_string()))?;
        }
    }
    root.present().map_err(|e| err(e.to_string()))
}
