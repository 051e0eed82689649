//! Speed-vs-error scatter charts as hand-written SVG (no plotting dependency).
//!
//! Both axes are logarithmic with a tick and a grid line at every power of ten (every second,
//! third … decade when the range is wide). Values the log scale cannot show are handled so that
//! no coordinate in the SVG is ever NaN or infinite, and the chart says what it did:
//!
//! - an error of exactly **0** goes into a grey band below the scale, labelled "0 (exact)";
//! - an **infinite or NaN** error goes into a grey band above the scale, labelled "∞ / NaN" (the
//!   report counts a NaN result as an infinite error);
//! - a point whose time is not positive and finite, or whose error is negative, is **not
//!   plotted**; its legend entry says so.
//!
//! Points carry a number next to the marker; the legend under the plot maps numbers to labels, so
//! long method names never overlap the data. The number's position is chosen among eight offsets
//! around the marker, avoiding the markers and the numbers already placed.

use std::fmt::Write as _;

/// One method on the chart.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Point {
    /// The legend text.
    pub(crate) label: String,
    /// Time (x, log scale); must be positive and finite to be plotted.
    pub(crate) x: f64,
    /// Error (y, log scale); 0 and ∞/NaN go into the bands outside the scale.
    pub(crate) y: f64,
    /// A peer (another library, or a port of one): drawn as an orange square instead of a blue
    /// circle.
    pub(crate) peer: bool,
    /// Drawn with a black ring (the crate's default method).
    pub(crate) highlight: bool,
    /// On the Pareto front: joined to the other such points by a dashed staircase.
    pub(crate) pareto: bool,
}

/// A scatter chart with logarithmic axes.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct ScatterChart {
    /// Shown above the plot.
    pub(crate) title: String,
    /// The x axis' label, with its unit.
    pub(crate) x_label: String,
    /// The y axis' label, with its unit.
    pub(crate) y_label: String,
    /// The points, numbered from 1 in this order.
    pub(crate) points: Vec<Point>,
    /// Extra lines shown under the plot, after the chart's own notes.
    pub(crate) notes: Vec<String>,
}

const WIDTH: f64 = 760.0;
const PLOT_LEFT: f64 = 96.0;
const PLOT_RIGHT: f64 = WIDTH - 24.0;
const PLOT_TOP: f64 = 52.0;
const PLOT_BOTTOM: f64 = 352.0;
/// Height of the "0" and "∞" bands.
const BAND: f64 = 26.0;
/// Gap between a band and the log scale.
const GAP: f64 = 16.0;
const LINE: f64 = 17.0;
const BLUE: &str = "#1f77b4";
const ORANGE: &str = "#e66100";
/// At most this many decade ticks on an axis; wider ranges label every k-th decade.
const MAX_TICKS: i32 = 10;
/// Legend labels are cut to this many characters.
const MAX_LABEL_CHARS: usize = 104;
/// Notes are wrapped at this many characters (11 px text).
const MAX_NOTE_CHARS: usize = 122;

/// Where a point's y lies.
#[derive(Clone, Copy, Debug, PartialEq)]
enum YPlace {
    Zero,
    Infinite,
    Log(f64),
}

fn y_place(y: f64) -> Option<YPlace> {
    if y.is_nan() || y == f64::INFINITY {
        Some(YPlace::Infinite)
    } else if y == 0.0 {
        Some(YPlace::Zero)
    } else if y > 0.0 {
        Some(YPlace::Log(y))
    } else {
        None
    }
}

fn x_plottable(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

/// A decade range `[10^lo, 10^hi]` mapped onto `[from, to]` pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
struct LogScale {
    lo: i32,
    hi: i32,
    from: f64,
    to: f64,
}

impl LogScale {
    /// The smallest decade range holding `values` (positive and finite), at least one decade.
    fn covering(values: impl Iterator<Item = f64>, from: f64, to: f64) -> Self {
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values {
            min = min.min(v.log10());
            max = max.max(v.log10());
        }
        let (mut lo, mut hi) = if min.is_finite() && max.is_finite() {
            // Saturating casts; log10 of a finite positive f64 is within ±324.
            (min.floor() as i32, max.ceil() as i32)
        } else {
            (0, 1)
        };
        if hi <= lo {
            hi = lo + 1;
        }
        // A point exactly on a decade would sit on the frame: give it some room.
        if min.is_finite() && min - f64::from(lo) < 0.05 {
            lo -= 1;
        }
        if max.is_finite() && f64::from(hi) - max < 0.05 {
            hi += 1;
        }
        Self { lo, hi, from, to }
    }

    fn map(&self, v: f64) -> f64 {
        let t = (v.log10() - f64::from(self.lo)) / f64::from(self.hi - self.lo);
        self.from + t * (self.to - self.from)
    }

    /// The decades that get a tick: all, or every k-th when there are too many.
    fn ticks(&self) -> Vec<i32> {
        let span = self.hi - self.lo;
        let step = (span + MAX_TICKS - 1) / MAX_TICKS;
        (self.lo..=self.hi)
            .filter(|e| (e - self.lo) % step.max(1) == 0)
            .collect()
    }

    /// Minor ticks at 2…9 × 10^k, only when every decade is labelled.
    fn minor_ticks(&self) -> Vec<f64> {
        if self.hi - self.lo > MAX_TICKS / 2 + 1 {
            return Vec::new();
        }
        (self.lo..self.hi)
            .flat_map(|e| (2..10).map(move |m| f64::from(m) * 10f64.powi(e)))
            .collect()
    }
}

/// `10` with a superscript exponent (`1` and `10` for 0 and 1).
fn power_of_ten(exponent: i32) -> String {
    match exponent {
        0 => "1".to_owned(),
        1 => "10".to_owned(),
        e => format!("10{}", super::table::superscript(e)),
    }
}

/// Escape the five XML special characters.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// A pixel coordinate with one decimal; a non-finite value (a bug) becomes 0 rather than `NaN`.
fn px(v: f64) -> String {
    debug_assert!(v.is_finite(), "non-finite SVG coordinate");
    if v.is_finite() {
        format!("{v:.1}")
    } else {
        "0".to_owned()
    }
}

/// An axis-aligned box, for label placement.
#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
}

impl Rect {
    fn overlap(&self, other: &Rect) -> f64 {
        let w = self.x1.min(other.x1) - self.x0.max(other.x0);
        let h = self.y1.min(other.y1) - self.y0.max(other.y0);
        if w > 0.0 && h > 0.0 { w * h } else { 0.0 }
    }
}

/// A plotted point: its number, pixel position and style.
struct Placed {
    number: usize,
    cx: f64,
    cy: f64,
    peer: bool,
    highlight: bool,
}

impl ScatterChart {
    /// The chart as a standalone SVG document.
    pub(crate) fn to_svg(&self) -> String {
        let plotted: Vec<(usize, &Point, YPlace)> = self
            .points
            .iter()
            .enumerate()
            .filter_map(|(i, p)| {
                let place = y_place(p.y)?;
                x_plottable(p.x).then_some((i + 1, p, place))
            })
            .collect();
        let has_zero = plotted.iter().any(|(_, _, y)| *y == YPlace::Zero);
        let has_inf = plotted.iter().any(|(_, _, y)| *y == YPlace::Infinite);
        let omitted: Vec<usize> = (1..=self.points.len())
            .filter(|n| !plotted.iter().any(|(m, _, _)| m == n))
            .collect();

        let log_top = if has_inf {
            PLOT_TOP + BAND + GAP
        } else {
            PLOT_TOP
        };
        let log_bottom = if has_zero {
            PLOT_BOTTOM - BAND - GAP
        } else {
            PLOT_BOTTOM
        };
        let xs = LogScale::covering(plotted.iter().map(|(_, p, _)| p.x), PLOT_LEFT, PLOT_RIGHT);
        let ys = LogScale::covering(
            plotted.iter().filter_map(|(_, _, y)| match y {
                YPlace::Log(v) => Some(*v),
                _ => None,
            }),
            log_bottom,
            log_top,
        );
        let zero_y = PLOT_BOTTOM - BAND / 2.0;
        let inf_y = PLOT_TOP + BAND / 2.0;

        let mut notes = vec![
            "Both axes are logarithmic. Blue circles: barytex; orange squares: peers (other \
             libraries, ports); ringed: the default."
                .to_owned(),
        ];
        if self.points.iter().any(|p| p.pareto) {
            notes.push(
                "Dashed line and ★: the Pareto front (no other method is at least as fast and as \
                 accurate, and better in one)."
                    .to_owned(),
            );
        }
        match (has_zero, has_inf) {
            (true, true) => notes.push(
                "Grey bands outside the scale: “0 (exact)” holds zero errors, “∞ / NaN” infinite \
                 or NaN ones."
                    .to_owned(),
            ),
            (true, false) => notes.push(
                "The grey band under the scale, “0 (exact)”, holds zero errors (a log scale has \
                 no 0)."
                    .to_owned(),
            ),
            (false, true) => notes.push(
                "The grey band over the scale, “∞ / NaN”, holds infinite or NaN errors.".to_owned(),
            ),
            (false, false) => {}
        }
        notes.extend(self.notes.iter().cloned());
        if !omitted.is_empty() {
            let list: Vec<String> = omitted.iter().map(ToString::to_string).collect();
            notes.push(format!(
                "Not plotted (time not positive and finite, or a negative error): {}.",
                list.join(", ")
            ));
        }

        let notes: Vec<String> = notes.iter().flat_map(|n| wrap(n, MAX_NOTE_CHARS)).collect();
        let notes_top = PLOT_BOTTOM + 66.0;
        let legend_top = notes_top + LINE * notes.len() as f64 + 10.0;
        let height = legend_top + LINE * self.points.len() as f64 + 8.0;

        let mut svg = String::new();
        let _ = writeln!(
            svg,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"sans-serif\" font-size=\"12\">",
            w = px(WIDTH),
            h = px(height)
        );
        let _ = writeln!(svg, "<title>{}</title>", escape(&self.title));
        let _ = writeln!(
            svg,
            "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"white\"/>",
            px(WIDTH),
            px(height)
        );
        let _ = writeln!(
            svg,
            "<text x=\"{}\" y=\"26\" text-anchor=\"middle\" font-size=\"15\" \
             font-weight=\"bold\">{}</text>",
            px(WIDTH / 2.0),
            escape(&self.title)
        );

        // Bands.
        for (present, top, label) in [
            (has_inf, PLOT_TOP, "∞ / NaN"),
            (has_zero, PLOT_BOTTOM - BAND, "0 (exact)"),
        ] {
            if present {
                let _ = writeln!(
                    svg,
                    "<rect class=\"band\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" \
                     fill=\"#ececec\"/>",
                    px(PLOT_LEFT),
                    px(top),
                    px(PLOT_RIGHT - PLOT_LEFT),
                    px(BAND)
                );
                let _ = writeln!(
                    svg,
                    "<text x=\"{}\" y=\"{}\" text-anchor=\"end\" font-size=\"11\">{}</text>",
                    px(PLOT_LEFT - 6.0),
                    px(top + BAND / 2.0 + 4.0),
                    escape(label)
                );
            }
        }

        // Grid, ticks and tick labels.
        let _ = writeln!(
            svg,
            "<g class=\"grid\" stroke=\"#dddddd\" stroke-width=\"1\">"
        );
        for v in xs.minor_ticks() {
            let x = xs.map(v);
            let _ = writeln!(
                svg,
                "<line x1=\"{x}\" y1=\"{}\" x2=\"{x}\" y2=\"{}\" stroke=\"#f2f2f2\"/>",
                px(PLOT_TOP),
                px(PLOT_BOTTOM),
                x = px(x)
            );
        }
        for v in ys.minor_ticks() {
            let y = ys.map(v);
            let _ = writeln!(
                svg,
                "<line x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#f2f2f2\"/>",
                px(PLOT_LEFT),
                px(PLOT_RIGHT),
                y = px(y)
            );
        }
        for e in xs.ticks() {
            let x = xs.map(10f64.powi(e));
            let _ = writeln!(
                svg,
                "<line class=\"xtick\" data-decade=\"{e}\" x1=\"{x}\" y1=\"{}\" x2=\"{x}\" \
                 y2=\"{}\"/>",
                px(PLOT_TOP),
                px(PLOT_BOTTOM),
                x = px(x)
            );
        }
        for e in ys.ticks() {
            let y = ys.map(10f64.powi(e));
            let _ = writeln!(
                svg,
                "<line class=\"ytick\" data-decade=\"{e}\" x1=\"{}\" y1=\"{y}\" x2=\"{}\" \
                 y2=\"{y}\"/>",
                px(PLOT_LEFT),
                px(PLOT_RIGHT),
                y = px(y)
            );
        }
        let _ = writeln!(svg, "</g>");
        for e in xs.ticks() {
            let _ = writeln!(
                svg,
                "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"11\">{}</text>",
                px(xs.map(10f64.powi(e))),
                px(PLOT_BOTTOM + 16.0),
                power_of_ten(e)
            );
        }
        for e in ys.ticks() {
            let _ = writeln!(
                svg,
                "<text x=\"{}\" y=\"{}\" text-anchor=\"end\" font-size=\"11\">{}</text>",
                px(PLOT_LEFT - 6.0),
                px(ys.map(10f64.powi(e)) + 4.0),
                power_of_ten(e)
            );
        }
        // Separators between the bands and the scale, then the frame.
        for (present, y) in [
            (has_inf, PLOT_TOP + BAND + GAP / 2.0),
            (has_zero, PLOT_BOTTOM - BAND - GAP / 2.0),
        ] {
            if present {
                let _ = writeln!(
                    svg,
                    "<line x1=\"{}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#888888\" \
                     stroke-dasharray=\"4 3\"/>",
                    px(PLOT_LEFT),
                    px(PLOT_RIGHT),
                    y = px(y)
                );
            }
        }
        let _ = writeln!(
            svg,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\"/>",
            px(PLOT_LEFT),
            px(PLOT_TOP),
            px(PLOT_RIGHT - PLOT_LEFT),
            px(PLOT_BOTTOM - PLOT_TOP)
        );
        // Axis labels.
        let _ = writeln!(
            svg,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>",
            px((PLOT_LEFT + PLOT_RIGHT) / 2.0),
            px(PLOT_BOTTOM + 38.0),
            escape(&self.x_label)
        );
        let y_mid = (PLOT_TOP + PLOT_BOTTOM) / 2.0;
        let _ = writeln!(
            svg,
            "<text x=\"18\" y=\"{y}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {y})\">{}\
             </text>",
            escape(&self.y_label),
            y = px(y_mid)
        );

        // Markers.
        let placed: Vec<Placed> = plotted
            .iter()
            .map(|(number, p, place)| Placed {
                number: *number,
                cx: xs.map(p.x),
                cy: match place {
                    YPlace::Zero => zero_y,
                    YPlace::Infinite => inf_y,
                    YPlace::Log(v) => ys.map(*v),
                },
                peer: p.peer,
                highlight: p.highlight,
            })
            .collect();
        // The Pareto front as a staircase: right along each point's error, then down to the next.
        let mut front: Vec<&Placed> = placed
            .iter()
            .filter(|p| self.points[p.number - 1].pareto)
            .collect();
        front.sort_by(|a, b| a.cx.total_cmp(&b.cx).then(b.cy.total_cmp(&a.cy)));
        if front.len() > 1 {
            let mut path = format!("M {} {}", px(front[0].cx), px(front[0].cy));
            for pair in front.windows(2) {
                let _ = write!(path, " H {} V {}", px(pair[1].cx), px(pair[1].cy));
            }
            let _ = writeln!(
                svg,
                "<path class=\"front\" d=\"{path}\" fill=\"none\" stroke=\"#777777\" \
                 stroke-width=\"1.2\" stroke-dasharray=\"5 3\"/>"
            );
        }
        for p in &placed {
            let point = &self.points[p.number - 1];
            let tooltip = format!("{}: {}", p.number, escape(&point.label));
            let (cx, cy) = (px(p.cx), px(p.cy));
            if p.highlight {
                let _ = writeln!(
                    svg,
                    "<circle cx=\"{cx}\" cy=\"{cy}\" r=\"8.5\" fill=\"none\" stroke=\"black\" \
                     stroke-width=\"1.5\"/>"
                );
            }
            if p.peer {
                let _ = writeln!(
                    svg,
                    "<rect class=\"point peer\" data-n=\"{n}\" x=\"{}\" y=\"{}\" width=\"9\" \
                     height=\"9\" fill=\"{ORANGE}\" fill-opacity=\"0.85\" stroke=\"white\">\
                     <title>{tooltip}</title></rect>",
                    px(p.cx - 4.5),
                    px(p.cy - 4.5),
                    n = p.number
                );
            } else {
                let _ = writeln!(
                    svg,
                    "<circle class=\"point\" data-n=\"{n}\" cx=\"{cx}\" cy=\"{cy}\" r=\"5\" \
                     fill=\"{BLUE}\" fill-opacity=\"0.85\" stroke=\"white\"><title>{tooltip}\
                     </title></circle>",
                    n = p.number
                );
            }
        }
        // Numbers next to the markers.
        for (x, y, anchor, number) in label_positions(&placed) {
            let _ = writeln!(
                svg,
                "<text class=\"number\" x=\"{}\" y=\"{}\" text-anchor=\"{anchor}\" \
                 font-size=\"11\" font-weight=\"bold\" fill=\"#222222\">{number}</text>",
                px(x),
                px(y)
            );
        }

        // Notes and legend.
        for (i, note) in notes.iter().enumerate() {
            let _ = writeln!(
                svg,
                "<text class=\"note\" x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#444444\">{}</text>",
                px(PLOT_LEFT - 70.0),
                px(notes_top + LINE * i as f64),
                escape(note)
            );
        }
        for (i, point) in self.points.iter().enumerate() {
            let n = i + 1;
            let y = legend_top + LINE * i as f64;
            let x = PLOT_LEFT - 62.0;
            if point.peer {
                let _ = writeln!(
                    svg,
                    "<rect x=\"{}\" y=\"{}\" width=\"9\" height=\"9\" fill=\"{ORANGE}\"/>",
                    px(x - 4.5),
                    px(y - 8.5)
                );
            } else {
                let _ = writeln!(
                    svg,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"5\" fill=\"{BLUE}\"/>",
                    px(x),
                    px(y - 4.0)
                );
            }
            if point.highlight {
                let _ = writeln!(
                    svg,
                    "<circle cx=\"{}\" cy=\"{}\" r=\"8\" fill=\"none\" stroke=\"black\" \
                     stroke-width=\"1.2\"/>",
                    px(x),
                    px(y - 4.0)
                );
            }
            let mut label = truncate(&point.label, MAX_LABEL_CHARS);
            if point.pareto {
                label.push_str(" ★");
            }
            if omitted.contains(&n) {
                label.push_str(" — not plotted");
            }
            let _ = writeln!(
                svg,
                "<text class=\"legend\" x=\"{}\" y=\"{}\"><tspan font-weight=\"bold\">{n}</tspan> \
                 {}</text>",
                px(x + 12.0),
                px(y),
                escape(&label)
            );
        }
        svg.push_str("</svg>\n");
        svg
    }
}

/// `text` broken at spaces into lines of at most `max_chars` characters (a longer word gets a
/// line of its own).
fn wrap(text: &str, max_chars: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let needed = line.chars().count() + usize::from(!line.is_empty()) + word.chars().count();
        if !line.is_empty() && needed > max_chars {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

fn truncate(text: &str, max_chars: usize) -> String {
    if text.chars().count() <= max_chars {
        text.to_owned()
    } else {
        let mut cut: String = text.chars().take(max_chars - 1).collect();
        cut.push('…');
        cut
    }
}

/// For each placed point, where its number goes: `(x, y, text-anchor, number)`, choosing among
/// eight offsets the first that overlaps no marker, no number placed before and stays inside the
/// plot (else the one with the least overlap).
fn label_positions(points: &[Placed]) -> Vec<(f64, f64, &'static str, usize)> {
    const CANDIDATES: [(f64, f64, &str); 8] = [
        (8.0, -6.0, "start"),
        (8.0, 13.0, "start"),
        (-8.0, -6.0, "end"),
        (-8.0, 13.0, "end"),
        (0.0, -10.0, "middle"),
        (0.0, 19.0, "middle"),
        (10.0, 4.0, "start"),
        (-10.0, 4.0, "end"),
    ];
    let markers: Vec<Rect> = points
        .iter()
        .map(|p| Rect {
            x0: p.cx - 6.0,
            y0: p.cy - 6.0,
            x1: p.cx + 6.0,
            y1: p.cy + 6.0,
        })
        .collect();
    let frame = Rect {
        x0: PLOT_LEFT,
        y0: PLOT_TOP,
        x1: PLOT_RIGHT,
        y1: PLOT_BOTTOM,
    };
    let mut taken: Vec<Rect> = Vec::new();
    let mut out = Vec::new();
    for (i, p) in points.iter().enumerate() {
        let width = 7.0 * p.number.to_string().len() as f64;
        let boxes = CANDIDATES.map(|(dx, dy, anchor)| {
            let x0 = match anchor {
                "start" => p.cx + dx,
                "end" => p.cx + dx - width,
                _ => p.cx + dx - width / 2.0,
            };
            let rect = Rect {
                x0,
                y0: p.cy + dy - 9.0,
                x1: x0 + width,
                y1: p.cy + dy + 1.0,
            };
            (dx, dy, anchor, rect)
        });
        // Numbers keep 2 px from each other.
        let padded = |r: &Rect| Rect {
            x0: r.x0 - 2.0,
            y0: r.y0 - 2.0,
            x1: r.x1 + 2.0,
            y1: r.y1 + 2.0,
        };
        let cost = |rect: &Rect| {
            let area = (rect.x1 - rect.x0) * (rect.y1 - rect.y0);
            let outside = area - rect.overlap(&frame);
            let hits: f64 = markers
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .map(|(_, m)| rect.overlap(m))
                .chain(taken.iter().map(|t| padded(rect).overlap(t)))
                .sum();
            hits + 2.0 * outside
        };
        let best = boxes
            .iter()
            .min_by(|a, b| cost(&a.3).total_cmp(&cost(&b.3)))
            .copied()
            .unwrap_or(boxes[0]);
        let (dx, dy, anchor, rect) = best;
        taken.push(rect);
        out.push((p.cx + dx, p.cy + dy, anchor, p.number));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(label: &str, x: f64, y: f64) -> Point {
        Point {
            label: label.to_owned(),
            x,
            y,
            peer: false,
            highlight: false,
            pareto: false,
        }
    }

    fn chart(points: Vec<Point>) -> ScatterChart {
        ScatterChart {
            title: "test chart".to_owned(),
            x_label: "time per call (ns)".to_owned(),
            y_label: "max abs error".to_owned(),
            points,
            notes: Vec::new(),
        }
    }

    /// Checks that `svg` is well-formed XML as far as this module writes it: balanced and
    /// properly nested tags, quoted attributes, no stray `<` or `&` in text. Returns the element
    /// names in document order.
    fn check_well_formed(svg: &str) -> Vec<String> {
        let mut stack: Vec<String> = Vec::new();
        let mut names = Vec::new();
        let mut rest = svg;
        let mut seen_root = false;
        while let Some(open) = rest.find('<') {
            check_text(&rest[..open]);
            let close = rest[open..].find('>').expect("unclosed tag") + open;
            let tag = &rest[open + 1..close];
            assert!(!tag.contains('<'), "'<' inside tag {tag:?}");
            if let Some(name) = tag.strip_prefix('/') {
                let top = stack.pop().expect("close tag without open tag");
                assert_eq!(top, name.trim(), "mismatched close tag");
            } else {
                let self_closing = tag.ends_with('/');
                let body = tag.trim_end_matches('/');
                let name = body
                    .split_whitespace()
                    .next()
                    .expect("empty tag")
                    .to_owned();
                check_attributes(&body[name.len()..]);
                if stack.is_empty() {
                    assert!(!seen_root, "second root element {name}");
                    seen_root = true;
                }
                names.push(name.clone());
                if !self_closing {
                    stack.push(name);
                }
            }
            rest = &rest[close + 1..];
        }
        check_text(rest);
        assert!(rest.trim().is_empty(), "text after the root: {rest:?}");
        assert!(stack.is_empty(), "unclosed elements: {stack:?}");
        assert_eq!(names.first().map(String::as_str), Some("svg"));
        names
    }

    fn check_text(text: &str) {
        let mut rest = text;
        while let Some(amp) = rest.find('&') {
            let end = rest[amp..].find(';').expect("bare '&'") + amp;
            let entity = &rest[amp + 1..end];
            assert!(
                ["amp", "lt", "gt", "quot", "apos"].contains(&entity),
                "unknown entity &{entity};"
            );
            rest = &rest[end + 1..];
        }
        assert!(!text.contains('>'), "raw '>' in text {text:?}");
    }

    fn check_attributes(attributes: &str) {
        let mut rest = attributes.trim();
        while !rest.is_empty() {
            let eq = rest.find('=').expect("attribute without value");
            let name = rest[..eq].trim();
            assert!(
                !name.is_empty()
                    && name
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == ':'),
                "bad attribute name {name:?}"
            );
            let after = &rest[eq + 1..];
            assert!(after.starts_with('"'), "unquoted attribute {name}");
            let end = after[1..].find('"').expect("unterminated attribute") + 1;
            check_text(&after[1..end]);
            rest = after[end + 1..].trim_start();
        }
    }

    /// The values of every numeric-looking attribute.
    fn numeric_attributes(svg: &str) -> Vec<String> {
        let mut out = Vec::new();
        for attr in [
            "x", "y", "x1", "x2", "y1", "y2", "cx", "cy", "width", "height",
        ] {
            let needle = format!(" {attr}=\"");
            let mut rest = svg;
            while let Some(at) = rest.find(&needle) {
                let start = at + needle.len();
                let end = rest[start..].find('"').expect("unterminated") + start;
                out.push(rest[start..end].to_owned());
                rest = &rest[end..];
            }
        }
        out
    }

    /// `(cx, cy)` of the circle marker numbered `n`.
    fn circle(svg: &str, n: usize) -> (f64, f64) {
        let needle = format!("class=\"point\" data-n=\"{n}\" ");
        let at = svg.find(&needle).expect("no such point");
        let attr = |name: &str| {
            let key = format!("{name}=\"");
            let start = svg[at..].find(&key).expect("no attribute") + at + key.len();
            let end = svg[start..].find('"').expect("unterminated") + start;
            svg[start..end].parse::<f64>().expect("not a number")
        };
        (attr("cx"), attr("cy"))
    }

    /// The x of the grid line at decade `e` on the x axis.
    fn x_tick(svg: &str, e: i32) -> f64 {
        let needle = format!("class=\"xtick\" data-decade=\"{e}\" x1=\"");
        let start = svg.find(&needle).expect("no such tick") + needle.len();
        let end = svg[start..].find('"').expect("unterminated") + start;
        svg[start..end].parse().expect("not a number")
    }

    #[test]
    fn svg_is_well_formed_with_the_expected_elements() {
        let mut peer = point("peer & co", 30.0, 1e-3);
        peer.peer = true;
        let mut default = point("default", 20.0, 6e-8);
        default.highlight = true;
        let svg = chart(vec![point("naive", 4.5, 1.3e-6), default, peer]).to_svg();
        let names = check_well_formed(&svg);
        for element in ["svg", "title", "text", "line", "circle", "rect", "tspan"] {
            assert!(names.iter().any(|n| n == element), "no <{element}>");
        }
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
        assert_eq!(svg.matches("class=\"point\"").count(), 2);
        assert_eq!(svg.matches("class=\"point peer\"").count(), 1);
        assert_eq!(svg.matches("class=\"legend\"").count(), 3);
        assert!(svg.contains(">test chart</text>"));
        assert!(svg.contains(">time per call (ns)</text>"));
        assert!(svg.contains(">max abs error</text>"));
        // Tick labels at powers of ten, e.g. 10⁻⁶ on the y axis and 10 on the x axis.
        assert!(svg.contains(">10⁻⁶</text>"), "{svg}");
        assert!(svg.contains(">10</text>"), "{svg}");
    }

    #[test]
    fn log_scale_places_ten_times_the_time_one_decade_right() {
        let svg = chart(vec![
            point("a", 3.0, 1e-5),
            point("b", 30.0, 1e-5),
            point("c", 300.0, 1e-3),
        ])
        .to_svg();
        let (ax, ay) = circle(&svg, 1);
        let (bx, by) = circle(&svg, 2);
        let (cx, cy) = circle(&svg, 3);
        let decade = x_tick(&svg, 2) - x_tick(&svg, 1);
        assert!(decade > 10.0, "decade {decade}");
        assert!((bx - ax - decade).abs() < 0.2, "{ax} {bx} {decade}");
        assert!((cx - bx - decade).abs() < 0.2, "{bx} {cx} {decade}");
        // 3 lies log10(3) of a decade right of the tick at 1.
        let one = x_tick(&svg, 0);
        assert!((ax - one - 3f64.log10() * decade).abs() < 0.2);
        // Equal errors at equal height; a larger error higher up (smaller y).
        assert!((ay - by).abs() < 0.05);
        assert!(cy < ay - 10.0);
    }

    #[test]
    fn zero_nan_and_infinite_values_never_reach_the_coordinates() {
        let svg = chart(vec![
            point("exact", 10.0, 0.0),
            point("nan error", 20.0, f64::NAN),
            point("infinite error", 30.0, f64::INFINITY),
            point("nan time", f64::NAN, 1e-3),
            point("infinite time", f64::INFINITY, 1e-3),
            point("zero time", 0.0, 1e-3),
            point("negative error", 5.0, -1.0),
            point("fine", 40.0, 1e-4),
        ])
        .to_svg();
        check_well_formed(&svg);
        for value in numeric_attributes(&svg) {
            let v: f64 = value
                .parse()
                .unwrap_or_else(|_| panic!("not a number: {value:?}"));
            assert!(v.is_finite(), "{value}");
        }
        assert!(!svg.to_lowercase().contains("\"nan\"") && !svg.contains("inf\""));
        // The zero and infinite errors are plotted in their bands, and the chart says so.
        assert!(svg.contains(">0 (exact)</text>"));
        assert!(svg.contains(">∞ / NaN</text>"));
        assert!(svg.contains("holds zero errors"));
        let (_, exact_y) = circle(&svg, 1);
        let (_, nan_y) = circle(&svg, 2);
        let (_, inf_y) = circle(&svg, 3);
        let (_, fine_y) = circle(&svg, 8);
        assert!(exact_y > fine_y && fine_y > inf_y && (nan_y - inf_y).abs() < 0.05);
        // The unplottable times and the negative error are omitted, and listed.
        assert_eq!(svg.matches("class=\"point\"").count(), 4);
        assert!(svg.contains(
            "Not plotted (time not positive and finite, or a negative error): 4, 5, 6, 7."
        ));
        assert_eq!(svg.matches(" — not plotted").count(), 4);
    }

    #[test]
    fn empty_and_degenerate_charts_are_well_formed() {
        for points in [
            Vec::new(),
            vec![point("only", 7.0, 3e-3)],
            vec![point("a", 10.0, 1.0), point("b", 10.0, 1.0)],
            vec![point("tiny", 1e-300, 1e-300), point("huge", 1e300, 1e300)],
        ] {
            let svg = chart(points).to_svg();
            check_well_formed(&svg);
            for value in numeric_attributes(&svg) {
                assert!(value.parse::<f64>().is_ok_and(f64::is_finite), "{value}");
            }
        }
        // A 600-decade range labels at most MAX_TICKS + 1 decades.
        let svg = chart(vec![point("tiny", 1e-300, 1.0), point("huge", 1e300, 1.0)]).to_svg();
        assert!(svg.matches("class=\"xtick\"").count() <= MAX_TICKS as usize + 1);
    }

    #[test]
    fn labels_are_escaped() {
        let svg = ScatterChart {
            title: "a < b & \"c\"".to_owned(),
            x_label: "x's <unit>".to_owned(),
            y_label: "y > 0".to_owned(),
            points: vec![point("geo `graham_hull(…, false)` <peer> & 'x'", 1.0, 1.0)],
            notes: vec!["note <&>".to_owned()],
        }
        .to_svg();
        check_well_formed(&svg);
        assert!(svg.contains("a &lt; b &amp; &quot;c&quot;"));
        assert!(svg.contains("x&apos;s &lt;unit&gt;"));
        assert!(svg.contains("y &gt; 0"));
        assert!(svg.contains("&lt;peer&gt; &amp; &apos;x&apos;"));
        assert!(!svg.contains("<peer>"));
        assert!(svg.contains("note &lt;&amp;&gt;"));
        assert_eq!(escape("<&>\"'"), "&lt;&amp;&gt;&quot;&apos;");
    }

    #[test]
    fn numbers_avoid_each_other_when_points_coincide() {
        let points: Vec<Point> = (0..4)
            .map(|i| point(&format!("p{i}"), 10.0, 1e-3))
            .collect();
        let placed: Vec<Placed> = (0..4)
            .map(|i| Placed {
                number: i + 1,
                cx: 300.0,
                cy: 200.0,
                peer: false,
                highlight: false,
            })
            .collect();
        let positions = label_positions(&placed);
        for (i, a) in positions.iter().enumerate() {
            for b in &positions[..i] {
                assert!(
                    (a.0, a.1, a.2) != (b.0, b.1, b.2),
                    "two numbers at the same place"
                );
            }
        }
        check_well_formed(&chart(points).to_svg());
    }

    #[test]
    fn pareto_front_is_a_staircase_through_its_points() {
        let mut points = vec![
            point("fast", 2.0, 1e-3),
            point("dominated", 50.0, 1e-2),
            point("exact", 100.0, 0.0),
            point("middle", 10.0, 1e-5),
        ];
        for i in [0, 2, 3] {
            points[i].pareto = true;
        }
        let svg = chart(points.clone()).to_svg();
        check_well_formed(&svg);
        let (fx, fy) = circle(&svg, 1);
        let (mx, my) = circle(&svg, 4);
        let (ex, ey) = circle(&svg, 3);
        let needle = "class=\"front\" d=\"";
        let start = svg.find(needle).expect("no front") + needle.len();
        let end = svg[start..].find('"').expect("unterminated") + start;
        let expected = format!(
            "M {} {} H {} V {} H {} V {}",
            px(fx),
            px(fy),
            px(mx),
            px(my),
            px(ex),
            px(ey)
        );
        assert_eq!(&svg[start..end], expected);
        // One point on the front: no line.
        for p in &mut points[2..] {
            p.pareto = false;
        }
        assert!(!chart(points).to_svg().contains("class=\"front\""));
    }

    #[test]
    fn power_of_ten_labels() {
        assert_eq!(power_of_ten(0), "1");
        assert_eq!(power_of_ten(1), "10");
        assert_eq!(power_of_ten(2), "10²");
        assert_eq!(power_of_ten(-7), "10⁻⁷");
        assert_eq!(power_of_ten(-10), "10⁻¹⁰");
        assert_eq!(power_of_ten(39), "10³⁹");
    }

    #[test]
    fn notes_wrap_at_spaces() {
        assert_eq!(wrap("a bb ccc dddd", 6), ["a bb", "ccc", "dddd"]);
        assert_eq!(wrap("unbreakable-word x", 4), ["unbreakable-word", "x"]);
        assert!(wrap("", 10).is_empty());
        let svg = ScatterChart {
            notes: vec!["word ".repeat(60)],
            ..chart(vec![point("a", 1.0, 1.0)])
        }
        .to_svg();
        assert!(svg.matches("class=\"note\"").count() >= 4);
    }

    #[test]
    fn long_labels_are_cut() {
        assert_eq!(truncate("short", 10), "short");
        let cut = truncate(&"é".repeat(200), MAX_LABEL_CHARS);
        assert_eq!(cut.chars().count(), MAX_LABEL_CHARS);
        assert!(cut.ends_with('…'));
    }
}
