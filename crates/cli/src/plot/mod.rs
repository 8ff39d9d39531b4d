//! A small plotting module: figures as lists of primitives, written as SVG
//! or rasterised to PNG, with 2-D axes and a sphere view to build them from.
//!
//! - [`figure`]: the backend-independent primitives (lines, fills, circles,
//!   text, colours) in figure pixels;
//! - [`svg`], [`png`]: the two backends;
//! - [`axes`]: a 2-D panel with nice ticks and labels;
//! - [`sphere`]: paths on the unit sphere in an orthographic view.
//!
//! Nothing here knows about tops: the subcommands build their figures from
//! these parts.

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
    /// The figure's size cannot be rasterised (zero or too large).
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
    pub fn from_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "svg" => Some(Self::Svg),
            "png" => Some(Self::Png),
            _ => None,
        }
    }

    /// The bytes of `figure` in this format.
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
