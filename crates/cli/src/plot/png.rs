//! Rasterises a [`Figure`] to a PNG image: anti-aliased paths with
//! `tiny-skia`, text as filled glyph outlines of the embedded DejaVu Sans
//! (read with `ttf-parser`; no system fonts, no hinting, no kerning).
//!
//! One figure pixel is one image pixel.

use tiny_skia::{
    FillRule, LineCap, LineJoin, Paint, Path, PathBuilder, Pixmap, Stroke as SkStroke, StrokeDash,
    Transform,
};
use ttf_parser::{Face, OutlineBuilder};

use super::PlotError;
use super::figure::{Anchor, Color, Figure, Primitive, Stroke, Text};

/// DejaVu Sans (Bitstream Vera licence, `assets/fonts/LICENSE-DejaVu.txt`).
pub static FONT: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../assets/fonts/DejaVuSans.ttf"
));

/// The PNG file for `figure`, `figure.width` × `figure.height` pixels, RGBA.
///
/// # Errors
/// [`PlotError::Size`] for a zero or too large size, [`PlotError::Font`] if
/// the embedded font does not parse, [`PlotError::Encode`] if PNG encoding fails.
pub fn render(figure: &Figure) -> Result<Vec<u8>, PlotError> {
    rasterise(figure)?
        .encode_png()
        .map_err(|e| PlotError::Encode(e.to_string()))
}

/// The figure drawn into a pixmap (premultiplied RGBA).
///
/// # Errors
/// As [`render`], without the encoding.
pub fn rasterise(figure: &Figure) -> Result<Pixmap, PlotError> {
    let size_error = PlotError::Size {
        width: figure.width,
        height: figure.height,
    };
    // 2^14 px per side is far beyond any plot; it bounds the memory.
    if figure.width > 1 << 14 || figure.height > 1 << 14 {
        return Err(size_error);
    }
    let mut pixmap = Pixmap::new(figure.width, figure.height).ok_or(size_error)?;
    let face = Face::parse(FONT, 0).map_err(|e| PlotError::Font(e.to_string()))?;
    pixmap.fill(sk_color(figure.background));
    for item in &figure.items {
        match item {
            Primitive::Polyline { points, stroke } => {
                let mut pb = PathBuilder::new();
                for (i, p) in points.iter().enumerate() {
                    if i == 0 {
                        pb.move_to(p.x as f32, p.y as f32);
                    } else {
                        pb.line_to(p.x as f32, p.y as f32);
                    }
                }
                if let Some(path) = pb.finish() {
                    stroke_path(&mut pixmap, &path, stroke);
                }
            }
            Primitive::Polygon {
                points,
                fill,
                stroke,
            } => {
                let mut pb = PathBuilder::new();
                for (i, p) in points.iter().enumerate() {
                    if i == 0 {
                        pb.move_to(p.x as f32, p.y as f32);
                    } else {
                        pb.line_to(p.x as f32, p.y as f32);
                    }
                }
                pb.close();
                if let Some(path) = pb.finish() {
                    fill_path(&mut pixmap, &path, *fill);
                    if let Some(stroke) = stroke {
                        stroke_path(&mut pixmap, &path, stroke);
                    }
                }
            }
            Primitive::Circle {
                center,
                radius,
                fill,
                stroke,
            } => {
                if let Some(path) =
                    PathBuilder::from_circle(center.x as f32, center.y as f32, *radius as f32)
                {
                    if let Some(fill) = fill {
                        fill_path(&mut pixmap, &path, *fill);
                    }
                    if let Some(stroke) = stroke {
                        stroke_path(&mut pixmap, &path, stroke);
                    }
                }
            }
            Primitive::Text(text) => draw_text(&mut pixmap, &face, text),
        }
    }
    Ok(pixmap)
}

/// tiny-skia's colour for ours.
fn sk_color(c: Color) -> tiny_skia::Color {
    tiny_skia::Color::from_rgba8(c.r, c.g, c.b, c.a)
}

/// A solid anti-aliased paint.
fn paint(color: Color) -> Paint<'static> {
    let mut paint = Paint::default();
    paint.set_color_rgba8(color.r, color.g, color.b, color.a);
    paint.anti_alias = true;
    paint
}

/// Fills `path` (non-zero rule).
fn fill_path(pixmap: &mut Pixmap, path: &Path, color: Color) {
    pixmap.fill_path(
        path,
        &paint(color),
        FillRule::Winding,
        Transform::identity(),
        None,
    );
}

/// Strokes `path` with round joins and caps.
fn stroke_path(pixmap: &mut Pixmap, path: &Path, stroke: &Stroke) {
    let dash = if stroke.dash.is_empty() {
        None
    } else {
        StrokeDash::new(stroke.dash.iter().map(|&d| d as f32).collect(), 0.0)
    };
    let sk = SkStroke {
        width: stroke.width as f32,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        dash,
        ..SkStroke::default()
    };
    pixmap.stroke_path(path, &paint(stroke.color), &sk, Transform::identity(), None);
}

/// The advance width of `text` at `size` px, in pixels.
pub fn text_width(face: &Face<'_>, text: &str, size: f64) -> f64 {
    let scale = size / f64::from(face.units_per_em());
    text.chars()
        .map(|c| {
            let id = glyph(face, c);
            f64::from(face.glyph_hor_advance(id).unwrap_or(0)) * scale
        })
        .sum()
}

/// The glyph for `c`, or the font's `?` (or .notdef) when it has none.
fn glyph(face: &Face<'_>, c: char) -> ttf_parser::GlyphId {
    face.glyph_index(c)
        .or_else(|| face.glyph_index('?'))
        .unwrap_or(ttf_parser::GlyphId(0))
}

/// Draws one line of text as filled glyph outlines.
fn draw_text(pixmap: &mut Pixmap, face: &Face<'_>, text: &Text) {
    let scale = text.size / f64::from(face.units_per_em());
    let width = text_width(face, &text.text, text.size);
    let start = match text.anchor {
        Anchor::Start => 0.0,
        Anchor::Middle => -width / 2.0,
        Anchor::End => -width,
    };
    let (sin, cos) = text.rotation.to_radians().sin_cos();
    let mut builder = GlyphPath {
        pb: PathBuilder::new(),
        map: [0.0; 6],
    };
    let mut pen = start;
    for c in text.text.chars() {
        let id = glyph(face, c);
        // Font units (y up) → text frame (x along the baseline, y down) →
        // rotation about the anchor → figure pixels.
        builder.map = [
            cos * scale,
            -sin * -scale,
            sin * scale,
            cos * -scale,
            text.at.x + cos * pen,
            text.at.y + sin * pen,
        ];
        let _ = face.outline_glyph(id, &mut builder);
        pen += f64::from(face.glyph_hor_advance(id).unwrap_or(0)) * scale;
    }
    if let Some(path) = builder.pb.finish() {
        fill_path(pixmap, &path, text.color);
    }
}

/// Collects glyph outlines into one path, mapping font units to pixels by
/// the affine map `[xx, xy, yx, yy, tx, ty]`: `x' = xx x + xy y + tx`,
/// `y' = yx x + yy y + ty`.
struct GlyphPath {
    pb: PathBuilder,
    map: [f64; 6],
}

impl GlyphPath {
    fn at(&self, x: f32, y: f32) -> (f32, f32) {
        let [xx, xy, yx, yy, tx, ty] = self.map;
        let (x, y) = (f64::from(x), f64::from(y));
        ((xx * x + xy * y + tx) as f32, (yx * x + yy * y + ty) as f32)
    }
}

impl OutlineBuilder for GlyphPath {
    fn move_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.pb.move_to(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.pb.line_to(x, y);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (x1, y1) = self.at(x1, y1);
        let (x, y) = self.at(x, y);
        self.pb.quad_to(x1, y1, x, y);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (x1, y1) = self.at(x1, y1);
        let (x2, y2) = self.at(x2, y2);
        let (x, y) = self.at(x, y);
        self.pb.cubic_to(x1, y1, x2, y2, x, y);
    }

    fn close(&mut self) {
        self.pb.close();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::figure::Point;

    #[test]
    fn draws_lines_and_text_and_encodes() {
        let mut fig = Figure::new(120, 40);
        fig.line(
            Point::new(0.0, 35.0),
            Point::new(120.0, 35.0),
            Stroke::solid(Color::rgb(255, 0, 0), 3.0),
        );
        fig.text(Text::new(
            Point::new(60.0, 25.0),
            "θ ≤ 1.5",
            20.0,
            Anchor::Middle,
        ));
        let pixmap = rasterise(&fig).unwrap();
        let px = |x: u32, y: u32| pixmap.pixel(x, y).unwrap();
        // The red line, and dark text pixels above it but not at the far left.
        assert_eq!((px(60, 35).red(), px(60, 35).green()), (255, 0));
        let dark = (0..120)
            .flat_map(|x| (5..28).map(move |y| (x, y)))
            .filter(|&(x, y)| px(x, y).red() < 100)
            .count();
        assert!(dark > 50, "{dark} dark pixels");
        assert_eq!(px(2, 15).red(), 255);
        let png = render(&fig).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        assert!(render(&Figure::new(0, 10)).is_err());
    }

    #[test]
    fn the_font_covers_greek_and_subscripts() {
        let face = Face::parse(FONT, 0).unwrap();
        for c in "θφψωαβ₁₂₃≤−·²".chars() {
            assert!(face.glyph_index(c).is_some(), "{c}");
        }
        let w = text_width(&face, "mm", 10.0);
        assert!((w - 2.0 * text_width(&face, "m", 10.0)).abs() < 1e-12 && w > 10.0);
    }
}
