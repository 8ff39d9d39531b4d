//! Writes a [`Figure`] as an SVG document, by hand (no dependency).
//!
//! Text uses the font family `DejaVu Sans, sans-serif`: the font the PNG
//! backend embeds, if the viewer has it. Numbers are rounded to 0.01 px.

use core::fmt::Write;

use crate::figure::{Anchor, Color, Figure, Point, Primitive, Stroke};

/// The SVG document for `figure`, ending with a newline.
///
/// ```
/// use kreisel_plot::Figure;
/// use kreisel_plot::figure::{Anchor, Point, Text};
///
/// let mut fig = Figure::new(120, 40);
/// fig.text(Text::new(Point::new(60.0, 25.0), "a < b", 14.0, Anchor::Middle));
/// let svg = kreisel_plot::svg::render(&fig);
/// assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
/// assert!(svg.contains(">a &lt; b</text>"));
/// ```
pub fn render(figure: &Figure) -> String {
    let mut out = String::new();
    let (w, h) = (figure.width, figure.height);
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, Verdana, sans-serif">"#
    );
    let _ = writeln!(
        out,
        r#"<rect x="0" y="0" width="{w}" height="{h}"{}/>"#,
        fill_attrs(figure.background)
    );
    for item in &figure.items {
        match item {
            Primitive::Polyline { points, stroke } => {
                let _ = writeln!(
                    out,
                    r#"<polyline points="{}" fill="none"{}/>"#,
                    point_list(points),
                    stroke_attrs(stroke)
                );
            }
            Primitive::Polygon {
                points,
                fill,
                stroke,
            } => {
                let _ = writeln!(
                    out,
                    r#"<polygon points="{}"{}{}/>"#,
                    point_list(points),
                    fill_attrs(*fill),
                    stroke.as_ref().map(stroke_attrs).unwrap_or_default()
                );
            }
            Primitive::Circle {
                center,
                radius,
                fill,
                stroke,
            } => {
                let _ = writeln!(
                    out,
                    r#"<circle cx="{}" cy="{}" r="{}"{}{}/>"#,
                    num(center.x),
                    num(center.y),
                    num(*radius),
                    fill.map_or_else(|| r#" fill="none""#.to_owned(), fill_attrs),
                    stroke.as_ref().map(stroke_attrs).unwrap_or_default()
                );
            }
            Primitive::Text(text) => {
                let anchor = match text.anchor {
                    Anchor::Start => "start",
                    Anchor::Middle => "middle",
                    Anchor::End => "end",
                };
                let (x, y) = (num(text.at.x), num(text.at.y));
                let rotate = if text.rotation == 0.0 {
                    String::new()
                } else {
                    format!(r#" transform="rotate({} {x} {y})""#, num(text.rotation))
                };
                let _ = writeln!(
                    out,
                    r#"<text x="{x}" y="{y}" font-size="{}" text-anchor="{anchor}"{}{rotate}>{}</text>"#,
                    num(text.size),
                    fill_attrs(text.color),
                    escape(&text.text)
                );
            }
        }
    }
    out.push_str("</svg>\n");
    out
}

/// A coordinate rounded to 0.01 px, without trailing zeros.
fn num(value: f64) -> String {
    let rounded = (value * 100.0).round() / 100.0;
    // −0 + 0 = +0: no "-0" in the output.
    format!("{}", rounded + 0.0)
}

/// `x1,y1 x2,y2 …`.
fn point_list(points: &[Point]) -> String {
    let mut out = String::with_capacity(points.len() * 14);
    for (i, p) in points.iter().enumerate() {
        if i > 0 {
            out.push(' ');
        }
        let _ = write!(out, "{},{}", num(p.x), num(p.y));
    }
    out
}

/// ` fill="#rrggbb"` and its opacity when not opaque.
fn fill_attrs(color: Color) -> String {
    if color.a == 255 {
        format!(r#" fill="{}""#, color.hex())
    } else {
        format!(
            r#" fill="{}" fill-opacity="{}""#,
            color.hex(),
            num(color.opacity())
        )
    }
}

/// ` stroke="…" stroke-width="…"`, opacity and dashes when needed.
fn stroke_attrs(stroke: &Stroke) -> String {
    let mut out = format!(
        r#" stroke="{}" stroke-width="{}" stroke-linejoin="round" stroke-linecap="round""#,
        stroke.color.hex(),
        num(stroke.width)
    );
    if stroke.color.a != 255 {
        let _ = write!(out, r#" stroke-opacity="{}""#, num(stroke.color.opacity()));
    }
    if !stroke.dash.is_empty() {
        let dash: Vec<String> = stroke.dash.iter().map(|&d| num(d)).collect();
        let _ = write!(out, r#" stroke-dasharray="{}""#, dash.join(" "));
    }
    out
}

/// Text with `&`, `<` and `>` escaped for XML character data.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::Text;

    #[test]
    fn writes_every_primitive() {
        let mut fig = Figure::new(200, 100);
        fig.polyline(
            vec![Point::new(0.0, 0.0), Point::new(10.004, -0.001)],
            Stroke::dashed(Color::rgb(255, 0, 0), 1.5, 4.0, 2.0),
        );
        fig.polygon(
            vec![
                Point::new(0.0, 0.0),
                Point::new(1.0, 0.0),
                Point::new(0.0, 1.0),
            ],
            Color::BLACK.with_alpha(51),
            None,
        );
        fig.circle(
            Point::new(5.0, 5.0),
            2.0,
            None,
            Some(Stroke::solid(Color::GREY, 1.0)),
        );
        fig.text(Text::new(Point::new(3.0, 4.0), "a < b & θ", 12.0, Anchor::Middle).rotated(-90.0));
        let svg = render(&fig);
        assert!(
            svg.starts_with(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\""
            )
        );
        assert!(
            svg.contains(
                r##"<polyline points="0,0 10,0" fill="none" stroke="#ff0000" stroke-width="1.5""##
            ),
            "{svg}"
        );
        assert!(svg.contains(r##"stroke-dasharray="4 2""##));
        assert!(svg.contains(r##"fill="#000000" fill-opacity="0.2""##));
        assert!(svg.contains(r##"<circle cx="5" cy="5" r="2" fill="none" stroke="#969696""##));
        assert!(
            svg.contains(r##"transform="rotate(-90 3 4)">a &lt; b &amp; θ</text>"##),
            "{svg}"
        );
        assert!(svg.ends_with("</svg>\n"));
    }
}
