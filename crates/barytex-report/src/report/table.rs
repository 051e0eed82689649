//! Result tables: rows of measured methods, the Pareto front, Markdown rendering.

use std::fmt::Write as _;

use super::chart::{Point, ScatterChart};
use crate::timing::median;

/// Maximum and median of per-input errors (a NaN error counts as infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ErrorStats {
    /// The largest error.
    pub(crate) max: f64,
    /// The median error.
    pub(crate) median: f64,
}

impl ErrorStats {
    /// Summarise per-input errors; `None` for an empty set.
    pub(crate) fn of(mut errors: Vec<f64>) -> Option<Self> {
        if errors.is_empty() {
            return None;
        }
        for e in &mut errors {
            if e.is_nan() {
                *e = f64::INFINITY;
            }
        }
        let max = errors.iter().copied().fold(0.0, f64::max);
        Some(Self {
            max,
            median: median(&mut errors),
        })
    }
}

/// One method measured on one input set.
#[derive(Clone, Debug, Default)]
pub(crate) struct Row {
    /// The method, as code (`barytex_interp::…`).
    pub(crate) method: String,
    /// Whether this is the crate's default (the function users are told to call).
    pub(crate) is_default: bool,
    /// Median nanoseconds per call.
    pub(crate) ns: f64,
    /// Absolute error per input (max over components).
    pub(crate) abs: Option<ErrorStats>,
    /// Error in f32 ulps of the exact value per input (max over components).
    pub(crate) ulps: Option<ErrorStats>,
    /// Largest ratio of error to the project's accuracy bar (`docs/ACCURACY.md`; ≤ 1 meets it).
    pub(crate) bar: Option<f64>,
    /// Results whose sign differs from the exact sign.
    pub(crate) wrong_signs: Option<usize>,
    /// Inputs classified differently from the exact classification.
    pub(crate) wrong_class: Option<usize>,
    /// Inputs with a NaN or infinite result (or an error where the exact answer exists).
    pub(crate) non_finite: Option<usize>,
    /// Not dominated in (time, error) within its table.
    pub(crate) pareto: bool,
}

impl Row {
    /// The error the Pareto front and the headlines use: max abs error if measured, else the
    /// number of wrong signs.
    fn primary_error(&self) -> f64 {
        match (self.abs, self.wrong_signs) {
            (Some(abs), _) => abs.max,
            (None, Some(wrong)) => wrong as f64,
            (None, None) => f64::INFINITY,
        }
    }

    fn primary_error_text(&self) -> String {
        match (self.abs, self.wrong_signs) {
            (Some(abs), _) => format!("max error {}", fmt_err(abs.max)),
            (None, Some(wrong)) => format!("{wrong} wrong signs"),
            (None, None) => "no error measure".to_owned(),
        }
    }
}

/// One input set of a family: every row measured on exactly these inputs.
#[derive(Clone, Debug, Default)]
pub(crate) struct Table {
    /// The input set's name.
    pub(crate) title: String,
    /// How the inputs were made.
    pub(crate) description: String,
    /// Number of inputs.
    pub(crate) inputs: usize,
    /// What a wrong sign is counted over (e.g. "of 3·N weights").
    pub(crate) sign_total: String,
    /// The measured methods.
    pub(crate) rows: Vec<Row>,
    /// Markdown appended after the table (per-case breakdowns).
    pub(crate) extra: Vec<String>,
    /// What one timing is per, for the chart's x axis ("pixel", "frame"…); empty: "call".
    pub(crate) time_unit: String,
    /// The chart's y-axis label, with its unit; empty: "max abs error" or "wrong signs
    /// (count)", whichever the table's error measure is.
    pub(crate) error_label: String,
    /// The file name of this table's speed-vs-error chart, set when the report writes one.
    pub(crate) chart: Option<String>,
}

impl Table {
    /// Mark every row that no other row beats in both time and primary error.
    pub(crate) fn mark_pareto(&mut self) {
        let keys: Vec<(f64, f64)> = self
            .rows
            .iter()
            .map(|r| (nan_to_inf(r.ns), nan_to_inf(r.primary_error())))
            .collect();
        for (i, row) in self.rows.iter_mut().enumerate() {
            let (t, e) = keys[i];
            row.pareto = !keys
                .iter()
                .enumerate()
                .any(|(j, &(tj, ej))| j != i && tj <= t && ej <= e && (tj < t || ej < e));
        }
    }

    /// This table's speed-vs-error chart (x: time, y: the error the Pareto front uses), or
    /// `None` when the table has no error measure or fewer than two rows.
    pub(crate) fn scatter_chart(&self, family: &str) -> Option<ScatterChart> {
        let has_abs = self.rows.iter().any(|r| r.abs.is_some());
        let has_signs = self.rows.iter().any(|r| r.wrong_signs.is_some());
        if self.rows.len() < 2 || !(has_abs || has_signs) {
            return None;
        }
        let y_label = if !self.error_label.is_empty() {
            self.error_label.clone()
        } else if has_abs {
            "max abs error".to_owned()
        } else {
            "wrong signs (count)".to_owned()
        };
        let unit = if self.time_unit.is_empty() {
            "call"
        } else {
            &self.time_unit
        };
        let points = self
            .rows
            .iter()
            .map(|row| {
                let mut label = row.method.replace('`', "");
                if row.is_default {
                    label.push_str(" (default)");
                }
                Point {
                    label,
                    x: row.ns,
                    y: row.primary_error(),
                    peer: is_peer(&row.method),
                    highlight: row.is_default,
                    pareto: row.pareto,
                }
            })
            .collect();
        Some(ScatterChart {
            title: format!("{family}: {}", self.title),
            x_label: format!("time per {unit} (ns)"),
            y_label,
            points,
            notes: Vec::new(),
        })
    }

    fn default_row(&self) -> Option<&Row> {
        self.rows.iter().find(|r| r.is_default)
    }

    fn render(&self, out: &mut String) {
        let _ = writeln!(out, "### {} ({} inputs)\n", self.title, self.inputs);
        if !self.description.is_empty() {
            let _ = writeln!(out, "{}\n", self.description);
        }
        let has = |f: &dyn Fn(&Row) -> bool| self.rows.iter().any(f);
        let (has_abs, has_ulps, has_bar) = (
            has(&|r| r.abs.is_some()),
            has(&|r| r.ulps.is_some()),
            has(&|r| r.bar.is_some()),
        );
        let (has_signs, has_class, has_nonfinite) = (
            has(&|r| r.wrong_signs.is_some()),
            has(&|r| r.wrong_class.is_some()),
            has(&|r| r.non_finite.is_some()),
        );
        let mut header = vec!["method", "ns/call", "time vs default"];
        if has_abs {
            header.extend(["max abs error", "median abs error"]);
        }
        if has_ulps {
            header.extend(["max ulps", "median ulps"]);
        }
        if has_bar {
            header.push("max error / bar");
        }
        let signs_header = format!("wrong signs ({})", self.sign_total);
        if has_signs {
            header.push(&signs_header);
        }
        if has_class {
            header.push("wrong class");
        }
        if has_nonfinite {
            header.push("non-finite / error");
        }
        header.push("Pareto");
        let _ = writeln!(out, "| {} |", header.join(" | "));
        let _ = writeln!(out, "|{}", "---|".repeat(header.len()));
        let default_ns = self.default_row().map_or(f64::NAN, |r| r.ns);
        for row in &self.rows {
            let mut cells = vec![
                if row.is_default {
                    format!("**{}** (default)", row.method)
                } else {
                    row.method.clone()
                },
                fmt_ns(row.ns),
                format!("{:.2}×", row.ns / default_ns),
            ];
            let opt = |v: Option<String>| v.unwrap_or_else(|| "–".to_owned());
            if has_abs {
                cells.push(opt(row.abs.map(|s| fmt_err(s.max))));
                cells.push(opt(row.abs.map(|s| fmt_err(s.median))));
            }
            if has_ulps {
                cells.push(opt(row.ulps.map(|s| fmt_ulps(s.max))));
                cells.push(opt(row.ulps.map(|s| fmt_ulps(s.median))));
            }
            if has_bar {
                cells.push(opt(row.bar.map(fmt_ulps)));
            }
            if has_signs {
                cells.push(opt(row.wrong_signs.map(|n| n.to_string())));
            }
            if has_class {
                cells.push(opt(row.wrong_class.map(|n| n.to_string())));
            }
            if has_nonfinite {
                cells.push(opt(row.non_finite.map(|n| n.to_string())));
            }
            cells.push(if row.pareto {
                "★".to_owned()
            } else {
                String::new()
            });
            let _ = writeln!(out, "| {} |", cells.join(" | "));
        }
        let _ = writeln!(out);
        if let Some(file) = &self.chart {
            let title: String = self
                .title
                .chars()
                .filter(|c| !matches!(c, '[' | ']'))
                .collect();
            let _ = writeln!(
                out,
                "![Speed vs error, {title}: one point per method, time and error on log scales]\
                 ({file})\n"
            );
        }
        for extra in &self.extra {
            let _ = writeln!(out, "{extra}\n");
        }
    }

    /// One sentence: the default against the fastest method of this table.
    fn headline(&self, family: &str) -> Option<String> {
        let default = self.default_row()?;
        let fastest = self
            .rows
            .iter()
            .filter(|r| r.ns.is_finite())
            .min_by(|a, b| a.ns.total_cmp(&b.ns))?;
        let mut line = format!(
            "**{family}, {}**: default `{}` {} ns/call, {}",
            self.title,
            default.method,
            fmt_ns(default.ns),
            default.primary_error_text()
        );
        if fastest.method != default.method {
            let _ = write!(
                line,
                "; fastest `{}` {} ns/call ({:.1}× faster), {}",
                fastest.method,
                fmt_ns(fastest.ns),
                default.ns / fastest.ns,
                fastest.primary_error_text()
            );
        }
        line.push('.');
        Some(line)
    }
}

/// One family of methods: its tables and notes.
#[derive(Clone, Debug, Default)]
pub(crate) struct Section {
    /// The family's heading (e.g. "2D barycentric").
    pub(crate) heading: String,
    /// What is compared and how the error is measured.
    pub(crate) intro: String,
    /// One table per input set.
    pub(crate) tables: Vec<Table>,
    /// Observations computed from the data, shown after the tables.
    pub(crate) notes: Vec<String>,
}

impl Section {
    /// Append the section's Markdown.
    pub(crate) fn render(&self, out: &mut String) {
        let _ = writeln!(out, "## {}\n", self.heading);
        let _ = writeln!(out, "{}\n", self.intro);
        for table in &self.tables {
            table.render(out);
        }
        if !self.notes.is_empty() {
            let _ = writeln!(out, "Observations (computed from the figures above):\n");
            for note in &self.notes {
                let _ = writeln!(out, "- {note}");
            }
            let _ = writeln!(out);
        }
    }

    /// One line per table for the index page.
    pub(crate) fn headlines(&self) -> Vec<String> {
        self.tables
            .iter()
            .filter_map(|t| t.headline(&self.heading))
            .collect()
    }
}

/// A Markdown matrix of per-case values: one row per case, one column per method.
pub(crate) fn per_case_matrix(
    caption: &str,
    cases: &[String],
    methods: &[String],
    values: &[Vec<String>],
) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{caption}\n");
    let _ = writeln!(out, "| case | {} |", methods.join(" | "));
    let _ = writeln!(out, "|{}", "---|".repeat(methods.len() + 1));
    for (case, row) in cases.iter().zip(values) {
        let _ = writeln!(out, "| {case} | {} |", row.join(" | "));
    }
    out.truncate(out.trim_end().len());
    out
}

/// Whether a method is a peer's (another library, or a port of one), from its name.
fn is_peer(method: &str) -> bool {
    method.contains("(peer") || method.starts_with("reference::")
}

fn nan_to_inf(x: f64) -> f64 {
    if x.is_nan() { f64::INFINITY } else { x }
}

/// Nanoseconds with three significant figures.
pub(crate) fn fmt_ns(ns: f64) -> String {
    if !ns.is_finite() {
        "–".to_owned()
    } else if ns >= 100.0 {
        format!("{ns:.0}")
    } else if ns >= 10.0 {
        format!("{ns:.1}")
    } else {
        format!("{ns:.2}")
    }
}

/// An absolute error: `0`, `∞`, or two significant figures in scientific notation.
pub(crate) fn fmt_err(e: f64) -> String {
    if e == 0.0 {
        "0".to_owned()
    } else if !e.is_finite() {
        "∞".to_owned()
    } else {
        format!("{e:.1e}")
    }
}

/// A count of ulps or a ratio: plain below 10 000, scientific above.
pub(crate) fn fmt_ulps(u: f64) -> String {
    if u == 0.0 {
        "0".to_owned()
    } else if !u.is_finite() {
        "∞".to_owned()
    } else if u < 10.0 {
        format!("{u:.2}")
    } else if u < 1e4 {
        format!("{u:.0}")
    } else {
        format!("{u:.1e}")
    }
}

/// `k` in superscript digits (and sign).
pub(super) fn superscript(k: i32) -> String {
    k.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
}
