//! # kreisel-plot
//!
//! Small static figures in pure Rust: a [`Figure`] is a size, a background
//! colour and a list of drawing primitives (polylines, filled polygons,
//! circles, text) in figure pixels, written as an SVG document or
//! rasterised to a PNG image, anti-aliased, with an embedded font
//! (DejaVu Sans). No system libraries and no system fonts: the same bytes
//! on every machine.
//!
//! - [`figure`]: the backend-independent primitives, colours, strokes and
//!   text, and polyline clipping;
//! - [`svg`], [`png`]: the two backends; [`png::draw_over_rgb`] also draws a
//!   figure over an existing `0x00RRGGBB` framebuffer (a window's pixels);
//! - [`axes`]: a 2-D panel mapping data onto a rectangle, with "nice"
//!   ticks, grid, tick labels, axis labels, a title, curves and markers;
//! - [`sphere`]: paths on the unit sphere in an orthographic view, the
//!   hidden hemisphere dimmed, and a magnified local view.
//!
//! The crate only draws: callers build their figures from these parts.
//!
//! ```
//! use kreisel_plot::axes::{Axes, Labels};
//! use kreisel_plot::figure::{Color, Rect, Stroke};
//! use kreisel_plot::{Figure, ImageFormat};
//!
//! let mut fig = Figure::new(640, 360);
//! let axes = Axes {
//!     frame: Rect { left: 70.0, top: 40.0, width: 540.0, height: 260.0 },
//!     x_range: (0.0, 10.0),
//!     y_range: (-1.0, 1.0),
//! };
//! axes.draw(&mut fig, &Labels { title: "sin t", x: "t (s)", y: "y" });
//! let curve: Vec<(f64, f64)> = (0..=200).map(|k| {
//!     let t = k as f64 * 0.05;
//!     (t, t.sin())
//! }).collect();
//! axes.curve(&mut fig, &curve, &Stroke::solid(Color::rgb(31, 119, 180), 2.0));
//! axes.marker(&mut fig, 5.0, 5f64.sin(), 4.0, Color::rgb(214, 39, 40));
//!
//! let svg = ImageFormat::Svg.render(&fig)?;
//! assert!(svg.starts_with(b"<svg"));
//! let png = ImageFormat::Png.render(&fig)?;
//! assert_eq!(&png[..4], b"\x89PNG");
//! # Ok::<(), kreisel_plot::PlotError>(())
//! ```

#![deny(missing_docs)]
#![forbid(unsafe_code)]

pub mod axes;
pub mod figure;
pub mod png;
pub mod sphere;
pub mod svg;

use std::path::Path;

pub use figure::Figure;

/// Why a figure could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The figure's size cannot be rasterised (zero, or over 16384 px a
    /// side), or the pixel buffer given does not have `width × height` pixels.
    #[error("cannot draw a {width} x {height} pixel image")]
    Size {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// The embedded font does not parse (a corrupted build).
    #[error("embedded font: {0}")]
    Font(String),
    /// PNG encoding failed.
    #[error("PNG encoding failed: {0}")]
    Encode(String),
}

/// An output file format for figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics (raster).
    Png,
}

impl ImageFormat {
    /// The format named by the file's extension (`.svg` or `.png`, any case).
    ///
    /// ```
    /// use std::path::Path;
    /// use kreisel_plot::ImageFormat;
    /// assert_eq!(ImageFormat::from_path(Path::new("out/top.PNG")), Some(ImageFormat::Png));
    /// assert_eq!(ImageFormat::from_path(Path::new("top.svg")), Some(ImageFormat::Svg));
    /// assert_eq!(ImageFormat::from_path(Path::new("top.jpg")), None);
    /// ```
    pub fn from_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "svg" => Some(Self::Svg),
            "png" => Some(Self::Png),
            _ => None,
        }
    }

    /// The bytes of `figure` in this format: the SVG document or the PNG file.
    ///
    /// # Errors
    /// [`PlotError`] from the PNG backend.
    pub fn render(self, figure: &Figure) -> Result<Vec<u8>, PlotError> {
        match self {
            Self::Svg => Ok(svg::render(figure).into_bytes()),
            Self::Png => png::render(figure),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_follow_the_extension() {
        assert_eq!(
            ImageFormat::from_path(Path::new("a/b.SVG")),
            Some(ImageFormat::Svg)
        );
        assert_eq!(
            ImageFormat::from_path(Path::new("x.png")),
            Some(ImageFormat::Png)
        );
        assert_eq!(ImageFormat::from_path(Path::new("x.jpg")), None);
        assert_eq!(ImageFormat::from_path(Path::new("png")), None);
    }
}
