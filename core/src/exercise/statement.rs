//! An exercise's statement as HTML: Markdown rendered by pulldown-cmark with raw HTML
//! turned into text (a statement cannot add markup, let alone script), links and images
//! with a scheme other than http, https and mailto dropped, and relative ones resolved
//! against the exercise file's own address.

use pulldown_cmark::{CowStr, Event, Options, Parser, Tag};

/// The HTML of a statement written in Markdown. `base` is the address of the exercise file
/// (`https://host/course/latch.toml`) that relative links and images are resolved
/// against; without it they stay as written.
pub fn statement_html(markdown: &str, base: Option<&str>) -> String {
    let options = Options::ENABLE_TABLES | Options::ENABLE_STRIKETHROUGH;
    let events = Parser::new_ext(markdown, options).map(|event| match event {
        Event::Html(text) | Event::InlineHtml(text) => Event::Text(text),
        Event::Start(Tag::Link { link_type, dest_url, title, id }) => {
            Event::Start(Tag::Link { link_type, dest_url: resolve(dest_url, base), title, id })
        }
        Event::Start(Tag::Image { link_type, dest_url, title, id }) => {
            Event::Start(Tag::Image { link_type, dest_url: resolve(dest_url, base), title, id })
        }
        other => other,
    });
    let mut html = String::new();
    pulldown_cmark::html::push_html(&mut html, events);
    html
}

/// The address of `name` in the folder of the file at `base` (`https://h/c/latch.toml`,
/// `starter.st` → `https://h/c/starter.st`): where an exercise's starter and the relative
/// links of its statement are.
pub fn next_to(base: &str, name: &str) -> String {
    let path_end = base.find(['?', '#']).unwrap_or(base.len());
    let folder = base[..path_end].rfind('/').map_or("", |i| &base[..=i]);
    format!("{folder}{name}")
}

/// A link's target made safe and absolute: `javascript:`, `data:` and other schemes
/// become empty; a relative target is joined to `base`'s folder (or its origin for `/x`).
fn resolve<'a>(url: CowStr<'a>, base: Option<&str>) -> CowStr<'a> {
    let text = url.trim();
    if let Some(colon) = text.find(':') {
        let scheme = &text[..colon];
        let is_scheme = !scheme.is_empty()
            && !scheme.contains(['/', '?', '#'])
            && scheme.chars().all(|c| c.is_ascii_alphanumeric() || "+-.".contains(c));
        if is_scheme {
            let allowed =
                ["http", "https", "mailto"].iter().any(|s| scheme.eq_ignore_ascii_case(s));
            return if allowed { url } else { CowStr::from("") };
        }
    }
    let Some(base) = base else { return url };
    if text.starts_with('#') || text.starts_with("//") {
        return url;
    }
    let joined = if text.starts_with('/') {
        // The origin: scheme://host
        let origin_end = base
            .find("://")
            .map(|i| base[i + 3..].find('/').map_or(base.len(), |j| i + 3 + j))
            .unwrap_or(0);
        format!("{}{text}", &base[..origin_end])
    } else {
        next_to(base, text)
    };
    CowStr::from(joined)
}

#[cfg(test)]
mod tests {
    use super::statement_html;

    #[test]
    fn markdown_becomes_html_and_raw_html_becomes_text() {
        let html = statement_html(
            "Press **Start**: `Motor` runs.\n\n<script>alert(1)</script>\n\nA <b>bold</b> word.",
            None,
        );
        assert!(html.contains("<strong>Start</strong>"), "{html}");
        assert!(html.contains("<code>Motor</code>"), "{html}");
        assert!(!html.contains("<script"), "{html}");
        assert!(html.contains("&lt;script&gt;"), "{html}");
        assert!(!html.contains("<b>"), "{html}");
    }

    #[test]
    fn script_links_are_dropped_and_relative_ones_resolved() {
        let html = statement_html(
            "[x](javascript:alert(1)) [y](JaVaScRiPt:alert(1)) ![d](data:text/html,hi) ![plant](img/tank.svg) [doc](/docs/a.md) [web](https://example.org/a)",
            Some("https://host.example/course/latch.toml?v=2"),
        );
        assert!(!html.to_lowercase().contains("javascript"), "{html}");
        assert!(!html.contains("data:"), "{html}");
        assert!(html.contains(r#"src="https://host.example/course/img/tank.svg""#), "{html}");
        assert!(html.contains(r#"href="https://host.example/docs/a.md""#), "{html}");
        assert!(html.contains(r#"href="https://example.org/a""#), "{html}");
    }

    #[test]
    fn without_a_base_relative_targets_stay() {
        let html = statement_html("![plant](img/tank.svg)", None);
        assert!(html.contains(r#"src="img/tank.svg""#), "{html}");
    }
}
