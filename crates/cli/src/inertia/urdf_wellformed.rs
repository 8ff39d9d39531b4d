//! What the XML parser leaves to `inertia --urdf`: how deep elements nest,
//! checked before parsing, and the XML declaration's version, checked after.
//!
//! roxmltree (0.20) parses an element's content by recursion, one call per
//! level of nesting, without a bound: a file of 14,000 nested elements
//! (100 kB) overflows the stack and aborts the process. [`check_depth`]
//! scans the text first, with a loop, and refuses a nesting deeper than
//! [`MAX_DEPTH`] — a URDF nests about five levels (`robot`, `link`,
//! `collision`, `geometry`, `mesh`). Comments, CDATA sections, processing
//! instructions and quoted attribute values are skipped as the XML grammar
//! says, so for every well-formed prefix the scan counts the depth the parser
//! reaches (document type declarations are refused by the parser, so no
//! entity can add elements).

/// Deepest element nesting accepted in a URDF (the root `<robot>` is 1).
pub const MAX_DEPTH: usize = 1000;

/// The end of the start tag that begins at `start` (just after its `>`),
/// skipping `>` inside quoted attribute values.
pub(super) fn start_tag_end(text: &str, start: usize) -> usize {
    let mut quote = None;
    for (i, b) in text.bytes().enumerate().skip(start) {
        match (quote, b) {
            (None, b'"' | b'\'') => quote = Some(b),
            (Some(q), _) if q == b => quote = None,
            (None, b'>') => return i + 1,
            _ => {}
        }
    }
    text.len()
}

/// The byte offset of the first start tag nested deeper than `max` levels.
pub fn too_deep(text: &str, max: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut at = 0;
    while let Some(k) = text[at..].find('<') {
        let start = at + k;
        let rest = &text[start..];
        let skip_to = |end: &str| rest.find(end).map_or(text.len(), |e| start + e + end.len());
        at = if rest.starts_with("<!--") {
            skip_to("-->")
        } else if rest.starts_with("<![CDATA[") {
            skip_to("]]>")
        } else if rest.starts_with("<?") {
            skip_to("?>")
        } else if rest.starts_with("<!") {
            skip_to(">")
        } else if rest.starts_with("</") {
            depth = depth.saturating_sub(1);
            skip_to(">")
        } else {
            let end = start_tag_end(text, start);
            if !text[..end].ends_with("/>") {
                depth += 1;
                if depth > max {
                    return Some(start);
                }
            }
            end
        };
    }
    None
}

/// The 1-based line of byte offset `pos`.
pub fn line_of(text: &str, pos: usize) -> u32 {
    let lines = text.as_bytes()[..pos]
        .iter()
        .filter(|&&b| b == b'\n')
        .count();
    u32::try_from(lines + 1).unwrap_or(u32::MAX)
}

/// The line of any byte offset, found by binary search (asking the parser,
/// which counts from the start each time, is quadratic on a file of many
/// elements).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LineIndex {
    newlines: Vec<usize>,
}

impl LineIndex {
    /// The index of `text`'s lines.
    pub fn new(text: &str) -> Self {
        let newlines = text
            .bytes()
            .enumerate()
            .filter_map(|(i, b)| (b == b'\n').then_some(i))
            .collect();
        Self { newlines }
    }

    /// The 1-based line of byte offset `pos`.
    pub fn line(&self, pos: usize) -> u32 {
        let before = self.newlines.partition_point(|&n| n < pos);
        u32::try_from(before + 1).unwrap_or(u32::MAX)
    }
}

/// A problem with the XML declaration (`<?xml version="1.0"?>`), which the
/// parser accepts with any version: `None` when it is absent or says 1.x.
pub fn declaration_problem(text: &str) -> Option<String> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let declaration = &text[..text.find("?>")?];
    if !declaration.starts_with("<?xml") {
        return None;
    }
    let after = declaration.split_once("version")?.1.trim_start();
    let after = after.strip_prefix('=')?.trim_start();
    let quote = after.chars().next()?;
    let value = after[1..].split(quote).next()?;
    if let Some(digits) = value.strip_prefix("1.")
        && !digits.is_empty()
        && digits.bytes().all(|b| b.is_ascii_digit())
    {
        return None;
    }
    Some(format!(
        "the XML declaration says version=\"{value}\"; XML versions are 1.0 and 1.x (the file would not load elsewhere)"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nested(n: usize) -> String {
        format!(
            "<robot>{}{}</robot>",
            "<a>".repeat(n - 1),
            "</a>".repeat(n - 1)
        )
    }

    #[test]
    fn depth_counts_open_elements_only() {
        assert_eq!(too_deep(&nested(3), 3), None);
        assert_eq!(too_deep(&nested(4), 3), Some("<robot><a><a>".len()));
        // Empty elements, comments, CDATA, instructions and quoted '>' are no levels.
        let flat = "<?xml version='1.0'?><robot><!-- <a><a> --><b x='>'/><![CDATA[<a><a>]]><?pi <a>?><c></c></robot>";
        assert_eq!(too_deep(flat, 2), None);
        assert_eq!(too_deep(flat, 1), Some(flat.find("<c>").unwrap()));
        assert_eq!(line_of("a\nb\nc", 4), 3);
        let index = LineIndex::new("a\nb\nc");
        assert_eq!([0, 1, 2, 3, 4].map(|p| index.line(p)), [1, 1, 2, 2, 3]);
    }

    #[test]
    fn the_version_must_be_one_point_something() {
        assert_eq!(declaration_problem("<?xml version=\"1.0\"?><robot/>"), None);
        assert_eq!(
            declaration_problem("\u{feff}<?xml version='1.1' encoding='UTF-8'?>"),
            None
        );
        assert_eq!(declaration_problem("<robot/>"), None);
        let e = declaration_problem("<?xml version=\"1 2\"?>\n<robot/>").unwrap();
        assert!(
            e.starts_with("the XML declaration says version=\"1 2\""),
            "{e}"
        );
        assert!(declaration_problem("<?xml version=\"2.0\"?><robot/>").is_some());
        assert!(declaration_problem("<?xml version=\"1.\"?><robot/>").is_some());
    }
}
