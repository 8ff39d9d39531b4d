//! Property tests of the URDF splice: on generated robots of any layout,
//! only the `<inertial>` elements change and the result is XML; on mutated
//! text, parsing and splicing never panic.

use std::path::Path;

use proptest::prelude::*;

use super::UrdfDocument;

/// One generated link: its layout and whether it has an inertial.
#[derive(Debug, Clone)]
struct LinkLayout {
    indent: &'static str,
    inline_child: bool,
    comment: bool,
    inertial: bool,
    single_quotes: bool,
}

fn link_layout() -> impl Strategy<Value = LinkLayout> {
    (
        prop::sample::select(vec!["", " ", "  ", "\t", "    "]),
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |(indent, inline_child, comment, inertial, single_quotes)| LinkLayout {
                indent,
                inline_child,
                comment,
                inertial,
                single_quotes,
            },
        )
}

/// A robot description with these links (each with one box collision).
fn robot(links: &[LinkLayout], crlf: bool) -> String {
    let nl = if crlf { "\r\n" } else { "\n" };
    let mut t = format!("<?xml version=\"1.0\"?>{nl}<!-- a > b -->{nl}<robot name=\"r\">{nl}");
    for (k, l) in links.iter().enumerate() {
        let q = if l.single_quotes { '\'' } else { '"' };
        let child = format!("{}{}", l.indent, l.indent);
        t += &format!("{}<link name={q}l{k}{q} note={q}>{q}>", l.indent);
        let sep = if l.inline_child {
            String::new()
        } else {
            format!("{nl}{child}")
        };
        if l.comment {
            t += &format!("{sep}<!-- <inertial> in a comment -->");
        }
        if l.inertial {
            t += &format!(
                "{sep}<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>"
            );
        }
        t += &format!(
            "{sep}<collision><geometry><box size=\"1 2 3\"/></geometry></collision>{nl}{}</link>{nl}",
            l.indent
        );
    }
    t + "</robot>" + nl
}

/// The text without its `<inertial>` elements and the whitespace before
/// each, back to and including the line break.
fn without_inertials(text: &str) -> String {
    let doc = roxmltree::Document::parse(text).expect("valid XML");
    let mut out = String::new();
    let mut done = 0;
    for n in doc.descendants().filter(|n| n.has_tag_name("inertial")) {
        let before = &text[done..n.range().start];
        let trimmed = before.trim_end_matches([' ', '\t']);
        let trimmed = trimmed.strip_suffix('\n').unwrap_or(trimmed);
        out.push_str(trimmed.strip_suffix('\r').unwrap_or(trimmed));
        done = n.range().end;
    }
    out + &text[done..]
}

proptest! {
    #[test]
    fn only_inertials_change(links in prop::collection::vec(link_layout(), 1..6), crlf in any::<bool>()) {
        let text = robot(&links, crlf);
        let doc = UrdfDocument::parse(Path::new("p.urdf"), text.clone()).unwrap();
        prop_assert_eq!(doc.links.len(), links.len());
        let elements: Vec<(usize, String)> = (0..links.len())
            .map(|k| (k, format!("<inertial><mass value=\"{k}\"/></inertial>")))
            .collect();
        let out = doc.splice(&elements);
        let parsed = roxmltree::Document::parse(&out).unwrap();
        for (k, link) in parsed.descendants().filter(|n| n.has_tag_name("link")).enumerate() {
            let inertials: Vec<_> = link.children().filter(|n| n.has_tag_name("inertial")).collect();
            prop_assert_eq!(inertials.len(), 1);
            let mass = inertials[0].first_element_child().unwrap().attribute("value");
            let want = k.to_string();
            prop_assert_eq!(mass, Some(want.as_str()));
        }
        prop_assert_eq!(without_inertials(&out), without_inertials(&text));
        prop_assert_eq!(doc.splice(&[]), text);
    }

    #[test]
    fn mutated_text_never_panics(cut in 0usize..2000, at in 0usize..2000, junk in "[<>\"'/= a-z&;!-]{0,6}") {
        let text = robot(&[link_layout_fixed(true), link_layout_fixed(false)], false);
        let cut = cut.min(text.len());
        let at = at.min(cut);
        if !text.is_char_boundary(cut) || !text.is_char_boundary(at) {
            return Ok(());
        }
        let mutated = format!("{}{junk}{}", &text[..at], &text[at..cut]);
        if let Ok(doc) = UrdfDocument::parse(Path::new("m.urdf"), mutated) {
            let elements: Vec<(usize, String)> =
                (0..doc.links.len()).map(|k| (k, "<inertial/>".to_owned())).collect();
            let _ = doc.splice(&elements);
        }
    }
}

/// A fixed layout, with or without an inertial.
fn link_layout_fixed(inertial: bool) -> LinkLayout {
    LinkLayout {
        indent: "  ",
        inline_child: false,
        comment: true,
        inertial,
        single_quotes: false,
    }
}
