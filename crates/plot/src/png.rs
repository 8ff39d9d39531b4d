//! Rasterises a [`Figure`]: to a PNG image ([`render`]), or over the pixels
//! of a window's framebuffer ([`draw_over_rgb`]). Anti-aliased paths with
//! `tiny-skia`, text as filled glyph outlines of the embedded DejaVu Sans
//! (read with `ttf-parser`; no system fonts, no hinting, no kerning).
//!
//! One figure pixel is one image pixel.

use tiny_skia::{
    FillRule, LineCap, LineJoin, Paint, Path, PathBuilder, Pixmap, PixmapMut, Stroke as SkStroke,
    StrokeDash, Transform,
};
use ttf_parser::{Face, OutlineBuilder};

use crate::PlotError;
use crate::figure::{Anchor, Color, Figure, Point, Primitive, Stroke, Text};

/// DejaVu Sans (Bitstream Vera licence, `assets/fonts/LICENSE-DejaVu.txt`).
pub(crate) static FONT: &[u8] = include_bytes!(concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../assets/fonts/DejaVuSans.ttf"
));

/// The largest width or height drawn, px: far beyond any plot, it bounds the memory.
const MAX_SIDE: u32 = 1 << 14;

/// The PNG file for `figure`, `figure.width` × `figure.height` pixels, RGBA.
///
/// ```
/// use kreisel_plot::Figure;
/// use kreisel_plot::figure::{Color, Point, Stroke};
///
/// let mut fig = Figure::new(40, 20);
/// fig.line(Point::new(0.0, 10.0), Point::new(40.0, 10.0), Stroke::solid(Color::BLACK, 2.0));
/// let png = kreisel_plot::png::render(&fig)?;
/// assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
/// assert!(kreisel_plot::png::render(&Figure::new(0, 20)).is_err());
/// # Ok::<(), kreisel_plot::PlotError>(())
/// ```
///
/// # Errors
/// [`PlotError::Size`] for a zero or too large size, [`PlotError::Font`] if
/// the embedded font does not parse, [`PlotError::Encode`] if PNG encoding fails.
pub fn render(figure: &Figure) -> Result<Vec<u8>, PlotError> {
    rasterise(figure)?
        .encode_png()
        .map_err(|e| PlotError::Encode(e.to_string()))
}

/// Draws the figure's primitives — not its background — over an existing
/// image of `figure.width` × `figure.height` pixels, row-major from the
/// top-left, each pixel `0x00RRGGBB` (the layout of a `minifb` window
/// buffer). The image is taken as opaque; the top byte of each pixel is
/// left as it is.
///
/// ```
/// use kreisel_plot::Figure;
/// use kreisel_plot::figure::{Color, Point};
///
/// let mut fig = Figure::new(20, 10);
/// fig.circle(Point::new(5.0, 5.0), 3.0, Some(Color::rgb(255, 0, 0)), None);
/// let mut frame = vec![0x0000_00ff_u32; 20 * 10]; // blue
/// kreisel_plot::png::draw_over_rgb(&fig, &mut frame)?;
/// assert_eq!(frame[5 * 20 + 5], 0x00ff_0000); // red under the circle
/// assert_eq!(frame[5 * 20 + 15], 0x0000_00ff); // blue elsewhere: no background
/// assert!(kreisel_plot::png::draw_over_rgb(&fig, &mut frame[1..]).is_err());
/// # Ok::<(), kreisel_plot::PlotError>(())
/// ```
///
/// # Errors
/// [`PlotError::Size`] when `pixels.len()` is not `width × height` or the
/// size is zero or too large, [`PlotError::Font`] if the embedded font does
/// not parse. `pixels` is unchanged on error.
pub fn draw_over_rgb(figure: &Figure, pixels: &mut [u32]) -> Result<(), PlotError> {
    check_size(figure)?;
    // At most 2^28 pixels: no overflow, even for a 32-bit usize.
    if pixels.len() != figure.width as usize * figure.height as usize {
        return Err(size_error(figure));
    }
    let face = font()?;
    let mut pixmap = Pixmap::new(figure.width, figure.height).ok_or_else(|| size_error(figure))?;
    // Opaque pixels: premultiplied RGBA is the straight colour. (Whole
    // words and fixed-size chunks, so that the loops vectorise.)
    for (rgba, &p) in pixmap
        .data_mut()
        .as_chunks_mut::<4>()
        .0
        .iter_mut()
        .zip(&*pixels)
    {
        *rgba = (0xff00_0000 | swap_red_blue(p)).to_le_bytes();
    }
    draw_items(&mut pixmap.as_mut(), &face, &figure.items);
    // Source-over onto an opaque pixel stays opaque: drop the alpha.
    for (p, rgba) in pixels.iter_mut().zip(pixmap.data().as_chunks::<4>().0) {
        *p = (*p & 0xff00_0000) | swap_red_blue(u32::from_le_bytes(*rgba));
    }
    Ok(())
}

/// The low three bytes of `word` with the lowest and the third swapped
/// (`0x..RRGGBB` ↔ `0x..BBGGRR`), the top byte cleared.
fn swap_red_blue(word: u32) -> u32 {
    ((word & 0xff) << 16) | (word & 0xff00) | ((word >> 16) & 0xff)
}

/// The figure drawn into a pixmap (premultiplied RGBA), background included.
///
/// # Errors
/// As [`render`], without the encoding.
pub(crate) fn rasterise(figure: &Figure) -> Result<Pixmap, PlotError> {
    check_size(figure)?;
    let face = font()?;
    let mut pixmap = Pixmap::new(figure.width, figure.height).ok_or_else(|| size_error(figure))?;
    pixmap.fill(sk_color(figure.background));
    draw_items(&mut pixmap.as_mut(), &face, &figure.items);
    Ok(pixmap)
}

/// [`PlotError::Size`] for the figure's size.
fn size_error(figure: &Figure) -> PlotError {
    PlotError::Size {
        width: figure.width,
        height: figure.height,
    }
}

/// Whether the figure's size can be drawn: neither side zero nor over [`MAX_SIDE`].
fn check_size(figure: &Figure) -> Result<(), PlotError> {
    let side = 1..=MAX_SIDE;
    if side.contains(&figure.width) && side.contains(&figure.height) {
        Ok(())
    } else {
        Err(size_error(figure))
    }
}

/// The embedded font, parsed.
fn font() -> Result<Face<'static>, PlotError> {
    Face::parse(FONT, 0).map_err(|e| PlotError::Font(e.to_string()))
}

/// Draws `items` in order (later ones on top): what [`render`] and
/// [`draw_over_rgb`] share.
fn draw_items(pixmap: &mut PixmapMut<'_>, face: &Face<'_>, items: &[Primitive]) {
    for item in items {
        match item {
            Primitive::Polyline { points, stroke } => {
                if let Some(path) = polygonal_path(points, false) {
                    stroke_path(pixmap, &path, stroke);
                }
            }
            Primitive::Polygon {
                points,
                fill,
                stroke,
            } => {
                if let Some(path) = polygonal_path(points, true) {
                    fill_path(pixmap, &path, *fill);
                    if let Some(stroke) = stroke {
                        stroke_path(pixmap, &path, stroke);
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
                        fill_path(pixmap, &path, *fill);
                    }
                    if let Some(stroke) = stroke {
                        stroke_path(pixmap, &path, stroke);
                    }
                }
            }
            Primitive::Text(text) => draw_text(pixmap, face, text),
        }
    }
}

/// The path through the vertices, closed if `close`; `None` when it has
/// no drawable extent (too few points).
fn polygonal_path(points: &[Point], close: bool) -> Option<Path> {
    let mut pb = PathBuilder::new();
    for (i, p) in points.iter().enumerate() {
        if i == 0 {
            pb.move_to(p.x as f32, p.y as f32);
        } else {
            pb.line_to(p.x as f32, p.y as f32);
        }
    }
    if close {
        pb.close();
    }
    pb.finish()
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

/// Fills `path` (non-zero rule); nothing for a fully transparent colour.
fn fill_path(pixmap: &mut PixmapMut<'_>, path: &Path, color: Color) {
    if color.a == 0 {
        return;
    }
    pixmap.fill_path(
        path,
        &paint(color),
        FillRule::Winding,
        Transform::identity(),
        None,
    );
}

/// Strokes `path` with round joins and caps; nothing for a fully
/// transparent colour.
fn stroke_path(pixmap: &mut PixmapMut<'_>, path: &Path, stroke: &Stroke) {
    if stroke.color.a == 0 {
        return;
    }
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
pub(crate) fn text_width(face: &Face<'_>, text: &str, size: f64) -> f64 {
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
fn draw_text(pixmap: &mut PixmapMut<'_>, face: &Face<'_>, text: &Text) {
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
    fn draws_over_a_framebuffer_without_the_background() {
        let (w, h) = (40_usize, 20_usize);
        let mut fig = Figure::new(w as u32, h as u32);
        fig.background = Color::BLACK;
        // A pixel-aligned rectangle: columns 10..30, rows 5..15.
        fig.polygon(
            vec![
                Point::new(10.0, 5.0),
                Point::new(30.0, 5.0),
                Point::new(30.0, 15.0),
                Point::new(10.0, 15.0),
            ],
            Color::rgb(0x12, 0x34, 0x56),
            None,
        );
        let teal = 0x0000_8080_u32;
        let mut pixels = vec![teal; w * h];
        draw_over_rgb(&fig, &mut pixels).unwrap();
        assert_eq!(pixels[10 * w + 20], 0x0012_3456, "centre");
        assert_eq!(pixels[18 * w + 2], teal, "far away");
        for (i, &p) in pixels.iter().enumerate() {
            let (x, y) = (i % w, i / w);
            let inside = (10..30).contains(&x) && (5..15).contains(&y);
            assert_eq!(p, if inside { 0x0012_3456 } else { teal }, "({x}, {y})");
        }
        // The top byte is kept.
        let mut marked = vec![0xff00_0000 | teal; w * h];
        draw_over_rgb(&fig, &mut marked).unwrap();
        assert_eq!(marked[10 * w + 20], 0xff12_3456);
        // A buffer of the wrong size is an error, and left alone.
        for len in [w * h - 1, w * h + 1, 0] {
            let mut wrong = vec![teal; len];
            assert!(matches!(
                draw_over_rgb(&fig, &mut wrong),
                Err(PlotError::Size {
                    width: 40,
                    height: 20
                })
            ));
            assert!(wrong.iter().all(|&p| p == teal));
        }
        assert!(draw_over_rgb(&Figure::new(0, 20), &mut []).is_err());
        assert!(draw_over_rgb(&Figure::new(1 << 15, 1), &mut vec![0; 1 << 15]).is_err());
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
