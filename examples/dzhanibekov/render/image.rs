//! Pixel images, clip rectangles and `0x00RRGGBB` colour helpers.

/// Packs 8-bit channels into a `0x00RRGGBB` pixel.
pub fn rgb(r: u8, g: u8, b: u8) -> u32 {
    (u32::from(r) << 16) | (u32::from(g) << 8) | u32::from(b)
}

/// Splits a `0x00RRGGBB` pixel into its 8-bit channels `(r, g, b)`.
pub fn channels(color: u32) -> (u8, u8, u8) {
    (
        ((color >> 16) & 0xFF) as u8,
        ((color >> 8) & 0xFF) as u8,
        (color & 0xFF) as u8,
    )
}

/// A row-major image of `0x00RRGGBB` pixels (minifb's buffer format).
///
/// `pixels.len()` should be `width * height`; drawing code checks this and
/// draws nothing into an inconsistent image instead of panicking.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Pixels, row by row from the top; pixel `(x, y)` is at `y * width + x`.
    pub pixels: Vec<u32>,
}

impl Image {
    /// Creates an image filled with `background`.
    pub fn new(width: usize, height: usize, background: u32) -> Self {
        Self {
            width,
            height,
            pixels: vec![background; width.saturating_mul(height)],
        }
    }

    /// Fills the whole image with `color`.
    pub fn clear(&mut self, color: u32) {
        self.pixels.fill(color);
    }

    /// The pixel at `(x, y)`, or `None` outside the image.
    pub fn pixel(&self, x: usize, y: usize) -> Option<u32> {
        if x >= self.width || y >= self.height {
            return None;
        }
        self.pixels
            .get(y.checked_mul(self.width)?.checked_add(x)?)
            .copied()
    }

    /// Sets the pixel at `(x, y)`; coordinates outside the image are ignored.
    pub fn set_pixel(&mut self, x: i64, y: i64, color: u32) {
        self.fill_rect(x, y, 1, 1, color);
    }

    /// Fills the rectangle with top-left corner `(x, y)` and size `w × h`,
    /// clipped to the image (negative or oversized rectangles are fine).
    pub fn fill_rect(&mut self, x: i64, y: i64, w: i64, h: i64, color: u32) {
        // An inconsistent image (buffer shorter than width × height) is left
        // alone; otherwise every index below is < width × height.
        if self
            .width
            .checked_mul(self.height)
            .is_none_or(|n| n > self.pixels.len())
        {
            return;
        }
        let width = i64::try_from(self.width).unwrap_or(i64::MAX);
        let height = i64::try_from(self.height).unwrap_or(i64::MAX);
        let x0 = x.clamp(0, width);
        let y0 = y.clamp(0, height);
        let x1 = x.saturating_add(w.max(0)).clamp(0, width);
        let y1 = y.saturating_add(h.max(0)).clamp(0, height);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        // All four are within 0..=width / 0..=height, so they fit in usize.
        let (x0, x1) = (x0 as usize, x1 as usize);
        for row in y0 as usize..y1 as usize {
            let start = row * self.width;
            if let Some(span) = self.pixels.get_mut(start + x0..start + x1) {
                span.fill(color);
            }
        }
    }
}

/// An axis-aligned pixel rectangle (e.g. the 3-D panel inside a frame).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipRect {
    /// Left column.
    pub x: usize,
    /// Top row.
    pub y: usize,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
}

impl ClipRect {
    /// A rectangle with top-left corner `(x, y)` and size `width × height`.
    pub fn new(x: usize, y: usize, width: usize, height: usize) -> Self {
        Self {
            x,
            y,
            width,
            height,
        }
    }

    /// The rectangle covering a whole `width × height` image.
    pub fn full(width: usize, height: usize) -> Self {
        Self::new(0, 0, width, height)
    }

    /// Exclusive right edge.
    pub fn right(&self) -> usize {
        self.x.saturating_add(self.width)
    }

    /// Exclusive bottom edge.
    pub fn bottom(&self) -> usize {
        self.y.saturating_add(self.height)
    }

    /// The overlap of two rectangles (empty if they are disjoint).
    pub fn intersect(&self, other: &ClipRect) -> ClipRect {
        let x = self.x.max(other.x);
        let y = self.y.max(other.y);
        let right = self.right().min(other.right());
        let bottom = self.bottom().min(other.bottom());
        ClipRect::new(x, y, right.saturating_sub(x), bottom.saturating_sub(y))
    }

    /// Whether the rectangle contains no pixel.
    pub fn is_empty(&self) -> bool {
        self.width == 0 || self.height == 0
    }

    /// Whether the screen point `(x, y)` (in pixels) lies inside.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        x >= self.x as f64
            && y >= self.y as f64
            && x < self.right() as f64
            && y < self.bottom() as f64
    }

    /// The centre of the rectangle in screen coordinates.
    pub fn center(&self) -> (f64, f64) {
        (
            self.x as f64 + self.width as f64 * 0.5,
            self.y as f64 + self.height as f64 * 0.5,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_util::{BG, WHITE};
    use super::*;

    #[test]
    fn image_fill_rect_clips() {
        let mut img = Image::new(8, 6, BG);
        img.fill_rect(-3, -2, 6, 4, WHITE);
        img.fill_rect(6, 4, i64::MAX, i64::MAX, WHITE);
        img.fill_rect(i64::MIN, 0, 5, 5, WHITE);
        img.fill_rect(2, 2, -5, 3, WHITE);
        img.set_pixel(100, 100, WHITE);
        for y in 0..6 {
            for x in 0..8 {
                let expect = (x < 3 && y < 2) || (x >= 6 && y >= 4);
                assert_eq!(img.pixel(x, y) == Some(WHITE), expect, "({x}, {y})");
            }
        }
        assert_eq!(img.pixel(8, 0), None);
        assert_eq!(rgb(0x12, 0x34, 0x56), 0x0012_3456);
        assert_eq!(channels(0x0012_3456), (0x12, 0x34, 0x56));
    }

    #[test]
    fn clip_rect_intersection() {
        let a = ClipRect::new(10, 10, 20, 20);
        let b = ClipRect::new(25, 0, 100, 15);
        assert_eq!(a.intersect(&b), ClipRect::new(25, 10, 5, 5));
        assert!(a.intersect(&ClipRect::new(40, 40, 5, 5)).is_empty());
        assert!(a.contains(10.0, 29.9) && !a.contains(30.0, 15.0));
    }
}
