//! Text from the user shown back in a message: control and invisible
//! characters written as `\u{…}`, so the message shows what is really
//! in the input.

/// `text` with every control or invisible character written as `\u{…}`, so
/// that an error message shows what is really in the input.
pub fn escape_invisible(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        let invisible = matches!(
            c,
            '\u{ad}'
                | '\u{115f}'
                | '\u{1160}'
                | '\u{180e}'
                | '\u{200b}'..='\u{200f}'
                | '\u{2028}'..='\u{202e}'
                | '\u{2060}'..='\u{206f}'
                | '\u{3164}'
                | '\u{fe00}'..='\u{fe0f}'
                | '\u{feff}'
                | '\u{fff9}'..='\u{fffb}'
        );
        if c.is_control() || invisible {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_and_invisible_characters_are_escaped() {
        assert_eq!(escape_invisible("a\u{200b}b\tc"), "a\\u{200b}b\\u{9}c");
        assert_eq!(escape_invisible("plain text, é"), "plain text, é");
    }
}
