//! Points (OpenGL 4.6 §14.4) and lines (§14.5, the diamond-exit rule) against hand-computed
//! pixels.

use std::sync::Mutex;

use barytex_raster::{
    Blend, DrawStats, Fragment, Framebuffer, LineTopology, PipelineState, SamplePattern, Shader,
    TargetLimits, draw_lines, draw_points,
};
use glam::{UVec2, Vec4};

/// Clip positions and a scalar varying given directly; records every fragment.
struct Record(Mutex<Vec<(UVec2, f32, f32)>>);

impl Shader for Record {
    type Vertex = (Vec4, f32);
    type Varying = f32;
    fn vertex(&self, v: &(Vec4, f32)) -> (Vec4, f32) {
        *v
    }
    fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
        self.0
            .lock()
            .expect("not poisoned")
            .push((f.pixel, f.varying, f.depth));
        Some(Vec4::ONE)
    }
}

/// A vertex at pixel coordinates `(x, y)` of an 8 × 8 target (y down), depth 0.5.
fn at(x: f32, y: f32) -> (Vec4, f32) {
    (Vec4::new(x / 4.0 - 1.0, 1.0 - y / 4.0, 0.5, 1.0), 0.0)
}

fn target() -> Framebuffer {
    Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default()).expect("small target")
}

/// The pixels the fragments landed on, in order.
fn lines(vertices: &[(Vec4, f32)], indices: &[u32], topology: LineTopology) -> Vec<(u32, u32)> {
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    let state = PipelineState {
        depth_compare: None,
        ..PipelineState::default()
    };
    draw_lines(&mut fb, &shader, &state, vertices, indices, topology);
    let seen = shader.0.into_inner().expect("not poisoned");
    seen.iter().map(|(p, _, _)| (p.x, p.y)).collect()
}

fn sorted(mut v: Vec<(u32, u32)>) -> Vec<(u32, u32)> {
    v.sort_unstable();
    v
}

#[test]
fn points_cover_the_pixel_whose_centre_is_in_their_half_open_square() {
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    // (2, 1.5) and (3, 1.5) are one pixel apart: their squares [1.5, 2.5) and [2.5, 3.5) share
    // the edge x = 2.5 through pixel (2, 1)'s centre, which only the right square keeps. So
    // the first covers pixel (1, 1), the second pixel (2, 1): one fragment each, none shared.
    // (6.5, 6.5) is pixel (6, 6)'s centre.
    let v = [at(2.0, 1.5), at(3.0, 1.5), at(6.5, 6.5)];
    let stats = draw_points(&mut fb, &shader, &PipelineState::default(), &v, &[0, 1, 2]);
    let seen: Vec<UVec2> = shader
        .0
        .into_inner()
        .expect("not poisoned")
        .iter()
        .map(|f| f.0)
        .collect();
    assert_eq!(seen, [UVec2::new(1, 1), UVec2::new(2, 1), UVec2::new(6, 6)]);
    assert_eq!(stats.points_in, 3);
    assert_eq!(stats.fragments_shaded, 3);
    assert_eq!(fb.pixel(1, 1), Some(Vec4::ONE));
    assert_eq!(fb.pixel(3, 1), Some(Vec4::ZERO));
}

#[test]
fn points_outside_the_view_volume_or_index_range_are_dropped() {
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    let behind = (Vec4::new(0.0, 0.0, -0.1, 1.0), 0.0); // z < 0: before the near plane
    let beside = (Vec4::new(1.5, 0.0, 0.5, 1.0), 0.0); // x > w
    let v = [behind, beside, at(4.5, 4.5)];
    let stats = draw_points(
        &mut fb,
        &shader,
        &PipelineState::default(),
        &v,
        &[0, 1, 2, 9],
    );
    assert_eq!(
        stats,
        DrawStats {
            points_in: 4,
            clipped_away: 2,
            dropped_bad_index: 1,
            fragments_shaded: 1,
            ..DrawStats::default()
        }
    );
    // The depth test applies: a second point at the same pixel, farther, fails.
    let far = (Vec4::new(0.125, -0.125, 0.75, 1.0), 0.0);
    let stats = draw_points(&mut fb, &shader, &PipelineState::default(), &[far], &[0]);
    assert_eq!(stats.fragments_depth_failed, 1);
    assert_eq!(fb.depth(4, 4), Some(0.5));
}

#[test]
fn multisampled_points_cover_the_samples_in_their_square() {
    // 2 × 2 regular samples at (¼, ¼), (¾, ¼), (¼, ¾), (¾, ¾) of each pixel. The point (2, 2)
    // has the square [1.5, 2.5)²: one sample in each of pixels (1, 1), (2, 1), (1, 2), (2, 2).
    let mut fb = Framebuffer::multisampled(
        8,
        8,
        SamplePattern::Regular { n: 2 },
        Vec4::ZERO,
        &TargetLimits::default(),
    )
    .expect("small target");
    let shader = Record(Mutex::new(Vec::new()));
    let stats = draw_points(
        &mut fb,
        &shader,
        &PipelineState::default(),
        &[at(2.0, 2.0)],
        &[0],
    );
    assert_eq!(stats.fragments_shaded, 4);
    for (x, y) in [(1, 1), (2, 1), (1, 2), (2, 2)] {
        // Straight alpha: the colour of the covered quarter, alpha ¼.
        assert_eq!(
            fb.pixel(x, y),
            Some(Vec4::new(1.0, 1.0, 1.0, 0.25)),
            "pixel ({x}, {y})"
        );
    }
    assert_eq!(fb.pixel(3, 2), Some(Vec4::ZERO));
}

#[test]
fn horizontal_lines_follow_the_diamonds_not_the_pixel_squares() {
    // On row 2's centre line, from x = 0.1 to 2.9: the segment starts inside pixel 0's diamond
    // (|0.1 − 0.5| < ½) and exits it, exits pixel 1's, and ends inside pixel 2's: two pixels.
    let v = [at(0.1, 2.5), at(2.9, 2.5)];
    assert_eq!(lines(&v, &[0, 1], LineTopology::List), [(0, 2), (1, 2)]);
    // 0.3 below the centre line the diamonds are 0.4 wide, x ∈ (c + 0.3, c + 0.7): the same
    // x-extent crosses all three, and ends outside pixel 2's.
    let v = [at(0.1, 2.8), at(2.9, 2.8)];
    assert_eq!(
        lines(&v, &[0, 1], LineTopology::List),
        [(0, 2), (1, 2), (2, 2)]
    );
    // Right to left: from pixel 5's centre to pixel 2's, the start drawn and the end not.
    let v = [at(5.5, 6.5), at(2.5, 6.5)];
    assert_eq!(
        sorted(lines(&v, &[0, 1], LineTopology::List)),
        [(3, 6), (4, 6), (5, 6)]
    );
}

#[test]
fn vertical_and_diagonal_lines() {
    // Column 4, from row 0's centre to row 4's: rows 0–3.
    let v = [at(4.5, 0.5), at(4.5, 4.5)];
    assert_eq!(
        lines(&v, &[0, 1], LineTopology::List),
        [(4, 0), (4, 1), (4, 2), (4, 3)]
    );
    // Slope 2/3 from (0.5, 0.5) to (3.5, 2.5): at the column centres x = 1.5, 2.5 the segment
    // is at y = 7/6 and 11/6, a third from row 1's centre (inside its diamond) and two thirds
    // from row 0's and row 2's; the end, pixel (3, 2)'s centre, is not drawn.
    let v = [at(0.5, 0.5), at(3.5, 2.5)];
    assert_eq!(
        lines(&v, &[0, 1], LineTopology::List),
        [(0, 0), (1, 1), (2, 1)]
    );
    // Steep (y-major), slope 1/3 in x per row: x = 11/6 at row 1's centre, 13/6 at row 2's.
    let v = [at(1.5, 0.5), at(2.5, 3.5)];
    assert_eq!(
        lines(&v, &[0, 1], LineTopology::List),
        [(1, 0), (1, 1), (2, 2)]
    );
    // Along a pixel boundary the tie goes to the column on the left (x = 3 → column 2).
    let v = [at(3.0, 1.5), at(3.0, 3.5)];
    assert_eq!(lines(&v, &[0, 1], LineTopology::List), [(2, 1), (2, 2)]);
}

#[test]
fn strips_and_loops_draw_each_shared_vertex_once() {
    let v = [at(0.5, 0.5), at(3.5, 0.5), at(3.5, 3.5)];
    let strip = lines(&v, &[0, 1, 2], LineTopology::Strip);
    // Row 0, columns 0–2; then column 3, rows 0–2; the strip's last vertex (3, 3) not drawn.
    assert_eq!(strip, [(0, 0), (1, 0), (2, 0), (3, 0), (3, 1), (3, 2)]);
    // The loop closes from (3.5, 3.5) back to (0.5, 0.5): (3, 3), (2, 2), (1, 1); (0, 0) was
    // drawn by the first segment.
    let closed = lines(&v, &[0, 1, 2], LineTopology::Loop);
    assert_eq!(closed.len(), 9);
    assert_eq!(&closed[..6], &strip[..]);
    assert_eq!(sorted(closed[6..].to_vec()), [(1, 1), (2, 2), (3, 3)]);
    // Blending "over" shows no pixel was written twice.
    let mut fb = target();
    let half = Vec4::new(1.0, 1.0, 1.0, 0.5);
    struct Half(Vec4);
    impl Shader for Half {
        type Vertex = (Vec4, f32);
        type Varying = f32;
        fn vertex(&self, v: &(Vec4, f32)) -> (Vec4, f32) {
            *v
        }
        fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
            Some(self.0)
        }
    }
    let state = PipelineState {
        depth_compare: None,
        blend: Blend::Over,
        ..PipelineState::default()
    };
    draw_lines(
        &mut fb,
        &Half(half),
        &state,
        &v,
        &[0, 1, 2],
        LineTopology::Loop,
    );
    for (x, y) in [(0, 0), (3, 0), (3, 3), (1, 1)] {
        let p = fb.pixel(x, y).expect("inside");
        assert!((p.w - 0.5).abs() < 1e-6, "pixel ({x}, {y}) alpha {}", p.w);
    }
}

#[test]
fn varyings_are_perspective_correct_and_depth_linear_along_a_line() {
    // From window (0, 4.5) at w = 1, z = 0 to window (8, 4.5) at w = 3, z = 1.5 (depth ½);
    // the varying goes 0 → 1. At column c, t = (c + ½)/8; the varying is
    // (t/3) / ((1 − t) + t/3) and the depth t/2. Column 7's diamond holds the end (x = 8 − ε).
    let y = -0.125;
    let v = [
        (Vec4::new(-1.0, y, 0.0, 1.0), 0.0),
        (Vec4::new(3.0, 3.0 * y, 1.5, 3.0), 1.0),
    ];
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    let stats = draw_lines(
        &mut fb,
        &shader,
        &PipelineState::default(),
        &v,
        &[0, 1],
        LineTopology::Strip,
    );
    let seen = shader.0.into_inner().expect("not poisoned");
    assert_eq!(seen.len(), 7);
    assert_eq!(stats.lines_in, 1);
    for (c, (pixel, varying, depth)) in seen.iter().enumerate() {
        assert_eq!(*pixel, UVec2::new(c as u32, 4));
        let t = (c as f32 + 0.5) / 8.0;
        let expected = (t / 3.0) / ((1.0 - t) + t / 3.0);
        assert!(
            (varying - expected).abs() < 1e-5,
            "column {c}: {varying} vs {expected}"
        );
        assert!((depth - t / 2.0).abs() < 1e-6, "column {c}: depth {depth}");
    }
    // Column 3: t = 7/16, varying 7/34.
    assert!((seen[3].1 - 7.0 / 34.0).abs() < 1e-6);
}

#[test]
fn lines_are_clipped_at_the_near_plane() {
    // From z = −0.5 (behind the near plane) at window x = 0 to z = 0.5 at x = 8, w = 1: the
    // clipped segment runs from x = 4 (t = ½) to 8. Moved by −ε, its start lies in column 3's
    // diamond (at its right corner), which it exits: columns 3–6. The varying is the original
    // segment's parameter, 0.5 + (x − 4)/8 at the pixel centre, clamped to the clipped segment
    // (0.5 in column 3).
    let y = -0.125;
    let v = [
        (Vec4::new(-1.0, y, -0.5, 1.0), 0.0),
        (Vec4::new(1.0, y, 0.5, 1.0), 1.0),
    ];
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    let stats = draw_lines(
        &mut fb,
        &shader,
        &PipelineState::default(),
        &v,
        &[0, 1],
        LineTopology::List,
    );
    assert_eq!(stats.clipped, 1);
    let seen = shader.0.into_inner().expect("not poisoned");
    let pixels: Vec<u32> = seen.iter().map(|f| f.0.x).collect();
    assert_eq!(pixels, [3, 4, 5, 6]);
    for (pixel, varying, _) in &seen {
        let expected = 0.5 + ((pixel.x as f32 + 0.5 - 4.0) / 8.0).max(0.0);
        assert!(
            (varying - expected).abs() < 1e-5,
            "{pixel}: {varying} vs {expected}"
        );
    }
    // Entirely behind: dropped.
    let behind = [
        (Vec4::new(-1.0, y, -0.5, 1.0), 0.0),
        (Vec4::new(1.0, y, -0.1, 1.0), 1.0),
    ];
    let stats = draw_lines(
        &mut fb,
        &Record(Mutex::new(Vec::new())),
        &PipelineState::default(),
        &behind,
        &[0, 1],
        LineTopology::List,
    );
    assert_eq!((stats.clipped_away, stats.fragments_shaded), (1, 0));
}

#[test]
fn hostile_points_and_lines_are_dropped_and_counted_never_written_outside() {
    let v = [
        (Vec4::new(f32::NAN, 0.0, 0.5, 1.0), 0.0),
        (Vec4::new(1e30, -1e30, 0.5, 1.0), 0.0), // far outside: the guard band clips it
        (Vec4::new(0.0, 0.0, 0.0, 0.0), 0.0),    // w = 0
        (Vec4::new(0.3, 0.2, -2.0, -1.0), 0.0),  // behind the eye
        (Vec4::new(0.1, 0.1, 0.5, 1.0), 0.0),
        (Vec4::new(f32::MAX, f32::MAX, f32::MAX, f32::MAX), 0.0),
    ];
    let all: Vec<u32> = (0..6).chain([99]).collect();
    // Every ordered pair, and one with a bad index.
    let pairs: Vec<u32> = (0..6)
        .flat_map(|a| (0..6).flat_map(move |b| [a, b]))
        .chain([4, 99])
        .collect();
    let shader = Record(Mutex::new(Vec::new()));
    let mut fb = target();
    let state = PipelineState {
        scissor: Some(barytex_raster::Scissor {
            x0: 2,
            y0: 2,
            x1: 6,
            y1: 6,
        }),
        ..PipelineState::default()
    };
    let points = draw_points(&mut fb, &shader, &state, &v, &all);
    assert_eq!(points.points_in, 7);
    assert_eq!(
        (points.dropped_bad_index, points.dropped_non_finite),
        (1, 1)
    );
    // The huge, w = 0 and behind-the-eye points are outside the view volume; the f32::MAX one
    // is NDC (1, 1, 1), on the volume's corner: kept, and its square covers no pixel centre.
    assert_eq!(points.clipped_away, 3);
    assert_eq!(points.fragments_shaded, 1);
    let lines = draw_lines(&mut fb, &shader, &state, &v, &pairs, LineTopology::List);
    assert_eq!(lines.lines_in, 37);
    assert_eq!(lines.dropped_bad_index, 1);
    assert_eq!(lines.dropped_non_finite, 11); // every pair with the NaN vertex
    for loop_or_strip in [LineTopology::Strip, LineTopology::Loop] {
        draw_lines(&mut fb, &shader, &state, &v, &all, loop_or_strip);
    }
    for (pixel, _, _) in shader.0.into_inner().expect("not poisoned") {
        assert!(
            (2..6).contains(&pixel.x) && (2..6).contains(&pixel.y),
            "{pixel}"
        );
    }
}

#[test]
fn points_and_lines_are_identical_for_any_thread_count() {
    struct Colour;
    impl Shader for Colour {
        type Vertex = (Vec4, f32);
        type Varying = f32;
        fn vertex(&self, v: &(Vec4, f32)) -> (Vec4, f32) {
            *v
        }
        fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
            Some(Vec4::new(f.varying, 1.0 - f.varying, 0.5, 0.5))
        }
    }
    // A fan of segments and points across a 4× multisampled target, blended "over" (order
    // dependent), at varying w.
    let v: Vec<(Vec4, f32)> = (0..40)
        .map(|i| {
            let a = i as f32 * 0.7;
            let w = 1.0 + (i % 5) as f32 * 0.5;
            (
                Vec4::new(a.cos() * 0.9 * w, a.sin() * 0.8 * w, 0.3 * w, w),
                i as f32 / 40.0,
            )
        })
        .collect();
    let indices: Vec<u32> = (0..40).collect();
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool");
        pool.install(|| {
            let mut fb = Framebuffer::multisampled(
                32,
                32,
                SamplePattern::Standard { count: 4 },
                Vec4::ZERO,
                &TargetLimits::default(),
            )
            .expect("small target");
            let state = PipelineState {
                blend: Blend::Over,
                depth_compare: None,
                ..PipelineState::default()
            };
            draw_lines(&mut fb, &Colour, &state, &v, &indices, LineTopology::Loop);
            draw_points(&mut fb, &Colour, &state, &v, &indices);
            fb
        })
    };
    let one = run(1);
    assert_eq!(one, run(3));
    assert_eq!(one, run(1));
}
