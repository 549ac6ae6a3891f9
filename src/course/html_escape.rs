//! Text made safe for the HTML pages and XML reports pbrlab writes (reports, similarity
//! pages, item analyses, JUnit XML), which print student-controlled text: one escaper for
//! all of them.

/// `text` safe as HTML or XML element content and as a quoted attribute value: the five
/// special characters as entities; control characters (other than tab), the two
/// non-characters XML forbids and the bidirectional overrides and isolates (which can make
/// code read differently from what it is) as U+FFFD.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 8);
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            '\t' => out.push('\t'),
            c if c.is_control()
                || matches!(
                    c,
                    '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}' | '\u{FFFE}' | '\u{FFFF}'
                ) =>
            {
                out.push('\u{FFFD}')
            }
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_special_character_and_every_control_and_bidi_override_is_neutralised() {
        assert_eq!(
            super::escape("<a title=\"y\" alt='x'>&</a>"),
            "&lt;a title=&quot;y&quot; alt=&#39;x&#39;&gt;&amp;&lt;/a&gt;"
        );
        assert_eq!(
            super::escape("a\u{202E}b\u{2066}c\u{0007}d\te"),
            "a\u{FFFD}b\u{FFFD}c\u{FFFD}d\te"
        );
    }
}
