//! Barycentric and inverse bilinear interpolation of your own vertex data.
//!
//! A weather grid stores a temperature and a wind vector at the corners of each (warped) quad
//! cell and at the vertices of a triangulated coastline. Given a query point, find where it lies
//! (exactly: inside, on an edge, on a vertex, outside) and interpolate the stored values.
//!
//! Run with `cargo run -p barytex-interp --example user_data`.

use barytex_interp::{
    InterpError, Interpolate, InverseBilinear, Location, barycentric_2d, bilinear,
    inverse_bilinear_2d, lerp,
};
use glam::Vec2;

/// What the grid stores at each vertex: your own type, interpolated as one value.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Sample {
    temperature: f32,
    wind: Vec2,
}

impl Interpolate for Sample {
    fn scale(self, w: f32) -> Self {
        Sample {
            temperature: self.temperature * w,
            wind: self.wind * w,
        }
    }
    fn add(self, other: Self) -> Self {
        Sample {
            temperature: self.temperature + other.temperature,
            wind: self.wind + other.wind,
        }
    }
    fn lerp(self, other: Self, t: f32) -> Self {
        // barytex's `lerp` is exact at t = 0 and t = 1 (the naive a + t·(b − a) is not).
        Sample {
            temperature: lerp(self.temperature, other.temperature, t),
            wind: self.wind.lerp(other.wind, t),
        }
    }
}

fn main() -> Result<(), InterpError> {
    // A coastline triangle and the samples at its vertices.
    let triangle = [
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(1.0, 3.0),
    ];
    let samples = [
        Sample {
            temperature: 12.0,
            wind: Vec2::new(1.0, 0.0),
        },
        Sample {
            temperature: 16.0,
            wind: Vec2::new(0.0, 2.0),
        },
        Sample {
            temperature: 9.0,
            wind: Vec2::new(-1.0, 1.0),
        },
    ];
    for query in [
        Vec2::new(1.5, 1.0),
        Vec2::new(2.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 5.0),
    ] {
        let b = barycentric_2d(query, triangle)?;
        let value = Sample::combine3(samples, b.weights);
        let where_ = match b.location {
            Location::Inside => "inside".to_string(),
            Location::OnEdge(i) => format!("on edge {i}"),
            Location::OnVertex(i) => format!("on vertex {i}"),
            Location::Outside => "outside (extrapolated)".to_string(),
            Location::Degenerate => "degenerate triangle".to_string(),
        };
        println!(
            "triangle: {query} is {where_}, weights {:?} -> {:.3} °C, wind {:.3}",
            b.weights, value.temperature, value.wind
        );
    }
    // On a vertex the weights are exactly (0, 1, 0): the stored sample comes back unchanged.
    let on_vertex = barycentric_2d(triangle[1], triangle)?;
    assert_eq!(Sample::combine3(samples, on_vertex.weights), samples[1]);

    // A warped grid cell (corners counter-clockwise from (α, β) = (0, 0)) and its samples.
    let cell = [
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(0.0, 2.0),
    ];
    let corners = [
        Sample {
            temperature: 10.0,
            wind: Vec2::X,
        },
        Sample {
            temperature: 14.0,
            wind: Vec2::Y,
        },
        Sample {
            temperature: 18.0,
            wind: -Vec2::X,
        },
        Sample {
            temperature: 11.0,
            wind: Vec2::ZERO,
        },
    ];
    for query in [
        Vec2::new(17.0 / 8.0, 5.0 / 8.0),
        Vec2::new(2.5, 1.5),
        Vec2::new(6.0, 0.0),
    ] {
        match inverse_bilinear_2d(query, cell)? {
            InverseBilinear::Inside(ab) => {
                let value = bilinear(corners, ab.x, ab.y);
                println!(
                    "cell: {query} has (α, β) = {ab:.6} -> {:.3} °C, wind {:.3}",
                    value.temperature, value.wind
                );
                // Round trip: the bilinear map sends (α, β) back to the query point.
                assert!((bilinear(cell, ab.x, ab.y) - query).length() < 1e-5);
            }
            InverseBilinear::Folded(first, second) => {
                println!("cell: {query} has two preimages {first} and {second} (folded cell)");
            }
            InverseBilinear::Outside(nearest) => {
                println!("cell: {query} is outside; nearest real preimage {nearest:?}");
            }
        }
    }
    Ok(())
}
