//! A tiny owned element tree read with quick-xml's event reader (namespaces dropped: only
//! local names are kept, which is what PLCopen files from every tool agree on).

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

use crate::diagnostics::Said;
use crate::limits::MAX_XML_DEPTH;

/// One XML element.
#[derive(Debug, Clone, Default)]
pub(crate) struct Node {
    /// Local name (`xhtml:p` → `p`).
    pub name: String,
    /// Attributes by local name, in document order.
    pub attrs: Vec<(String, String)>,
    /// Child elements in document order.
    pub children: Vec<Node>,
    /// Concatenated character data directly inside this element (text and CDATA).
    pub text: String,
    /// 1-based line of its start tag in the file.
    pub line: u32,
    /// 1-based column of its start tag.
    pub column: u32,
    /// 1-based line and column where [`Node::text`] begins in the file (its first text or
    /// CDATA content).
    pub text_at: Option<(u32, u32)>,
}

impl Node {
    /// The attribute `name`, if present.
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attrs.iter().find(|(k, _)| k == name).map(|(_, v)| v.as_str())
    }

    /// The first child named `name`.
    pub fn child(&self, name: &str) -> Option<&Node> {
        self.children.iter().find(|c| c.name == name)
    }

    /// Every child named `name`.
    pub fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Node> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }

    /// All text inside this element and its descendants, in document order.
    pub fn deep_text(&self) -> String {
        let mut out = self.text.clone();
        for c in &self.children {
            out.push_str(&c.deep_text());
        }
        out
    }
}

fn start_node(e: &BytesStart<'_>, at: crate::diagnostics::Location) -> Result<Node, Said> {
    let name = e.local_name().as_ref().to_string();
    let mut attrs = Vec::new();
    for a in e.attributes() {
        let a =
            a.map_err(|err| crate::msg!(XmlBadAttribute, name = &name, error = err.to_string()))?;
        let key = a.key.local_name().as_ref().to_string();
        let value = a
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|err| {
                crate::msg!(
                    XmlBadAttributeValue,
                    key = format!("{key:?}"),
                    name = &name,
                    error = err.to_string()
                )
            })?
            .into_owned();
        attrs.push((key, value));
    }
    Ok(Node {
        name,
        attrs,
        children: Vec::new(),
        text: String::new(),
        line: at.line,
        column: at.column,
        text_at: None,
    })
}

/// Why a document is not well-formed XML, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct XmlError {
    /// What is wrong (its English text is `message.english`; the XML reader's own words,
    /// quick-xml's, stay English in every language).
    pub message: Said,
    /// 1-based line of the place the reader stopped at.
    pub line: u32,
    /// 1-based column.
    pub column: u32,
}

impl XmlError {
    /// The error as one message, `line 1, column 2: …`, to be shown in any language; its
    /// English text is the error's `Display`.
    pub fn said(&self) -> Said {
        crate::msg!(XmlAt, line = self.line, column = self.column, message = &self.message)
    }
}

impl std::fmt::Display for XmlError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.said().english)
    }
}

/// Parses a whole document and returns its root element.
pub(crate) fn parse(xml: &str) -> Result<Node, XmlError> {
    let mut at = Cursor { text: xml, offset: 0, line: 1, column: 1 };
    parse_at(xml, &mut at).map_err(|message| XmlError { message, line: at.line, column: at.column })
}

/// The line and column of a place in the text, moved forward from the last place asked
/// for: reading a document costs one pass over it, however long its lines (a file saved
/// on one line would otherwise count its columns from the start for every element).
struct Cursor<'a> {
    text: &'a str,
    offset: usize,
    line: u32,
    column: u32,
}

impl Cursor<'_> {
    /// Moves to byte `offset` (never backwards) and returns its place.
    fn advance(&mut self, offset: usize) -> crate::diagnostics::Location {
        if let Some(passed) = self.text.get(self.offset..offset) {
            for c in passed.chars() {
                if c == '\n' {
                    self.line += 1;
                    self.column = 1;
                } else {
                    self.column += 1;
                }
            }
            self.offset = offset;
        }
        crate::diagnostics::Location { line: self.line, column: self.column }
    }
}

/// [`parse`], keeping in `cursor` the place of the last event read.
fn parse_at(xml: &str, cursor: &mut Cursor<'_>) -> Result<Node, Said> {
    let mut reader = Reader::from_str(xml);
    let mut stack: Vec<Node> = Vec::new();
    let mut root: Option<Node> = None;
    loop {
        let pos = reader.buffer_position();
        let at = cursor.advance(usize::try_from(pos).unwrap_or(usize::MAX));
        let event = reader.read_event().map_err(|e| reader_said(&e))?;
        match event {
            Event::Start(e) => {
                if stack.len() >= MAX_XML_DEPTH {
                    return Err(crate::msg!(XmlNestedTooDeep, depth = MAX_XML_DEPTH));
                }
                stack.push(start_node(&e, at)?)
            }
            Event::Empty(e) => {
                let node = start_node(&e, at)?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(node),
                    None if root.is_none() => root = Some(node),
                    None => return Err(crate::msg!(XmlSeveralRoots)),
                }
            }
            Event::End(_) => {
                let node = stack.pop().ok_or_else(|| crate::msg!(XmlUnbalancedEndTag))?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(node),
                    None if root.is_none() => root = Some(node),
                    None => return Err(crate::msg!(XmlSeveralRoots)),
                }
            }
            Event::Text(t) => {
                if let Some(top) = stack.last_mut() {
                    top.text_at.get_or_insert((at.line, at.column));
                    top.text.push_str(&t.xml10_content());
                }
            }
            Event::CData(t) => {
                if let Some(top) = stack.last_mut() {
                    // The content begins after `<![CDATA[`.
                    top.text_at.get_or_insert((at.line, at.column + 9));
                    top.text.push_str(&t.into_inner());
                }
            }
            Event::GeneralRef(r) => {
                let resolved = match r.resolve_char_ref() {
                    Ok(Some(c)) => c.to_string(),
                    Ok(None) => {
                        let name = r.into_inner().into_owned();
                        quick_xml::escape::resolve_predefined_entity(&name)
                            .ok_or_else(|| crate::msg!(XmlUnknownEntity, name = &name))?
                            .to_string()
                    }
                    Err(e) => {
                        return Err(crate::msg!(XmlBadCharacterReference, error = e.to_string()))
                    }
                };
                if let Some(top) = stack.last_mut() {
                    top.text.push_str(&resolved);
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    if !stack.is_empty() {
        return Err(crate::msg!(XmlEndsInsideElement));
    }
    root.ok_or_else(|| crate::msg!(XmlNoRoot))
}

/// Escapes text for element content and attribute values.
pub(crate) fn esc(s: &str) -> String {
    quick_xml::escape::escape(s).into_owned()
}

/// quick-xml's error as a message: its words (English `Display`, kept exactly) in the
/// language asked for the errors a hand-edited file meets; any other stays quick-xml's text.
pub(crate) fn reader_said(e: &quick_xml::Error) -> Said {
    use crate::msg;
    use quick_xml::errors::{IllFormedError as I, SyntaxError as S};
    match e {
        quick_xml::Error::Syntax(s) => {
            let what = match s {
                S::InvalidBangMarkup => msg!(XmlqInvalidBangMarkup),
                S::UnclosedPI => msg!(XmlqUnclosedPi),
                S::UnclosedXmlDecl => msg!(XmlqUnclosedXmlDecl),
                S::UnclosedComment => msg!(XmlqUnclosedComment),
                S::UnclosedDoctype => msg!(XmlqUnclosedDoctype),
                S::UnclosedCData => msg!(XmlqUnclosedCdata),
                S::UnclosedTag => msg!(XmlqUnclosedTag),
                S::UnclosedSingleQuotedAttributeValue => msg!(XmlqUnclosedSingleQuoted),
                S::UnclosedDoubleQuotedAttributeValue => msg!(XmlqUnclosedDoubleQuoted),
            };
            msg!(XmlqSyntax, what = what)
        }
        quick_xml::Error::IllFormed(i) => {
            let what = match i {
                I::MissingEndTag(tag) => msg!(XmlqMissingEndTag, tag = tag),
                I::UnmatchedEndTag(tag) => msg!(XmlqUnmatchedEndTag, tag = tag),
                I::MismatchedEndTag { expected, found } => {
                    msg!(XmlqMismatchedEndTag, expected = expected, found = found)
                }
                I::DoubleHyphenInComment => msg!(XmlqDoubleHyphenInComment),
                I::UnclosedReference => msg!(XmlqUnclosedReference),
                other => Said::from(other.to_string()),
            };
            msg!(XmlqIllFormed, what = what)
        }
        other => Said::from(other.to_string()),
    }
}

#[cfg(test)]
mod reader_tests {
    use super::*;
    use crate::i18n::Lang;

    #[test]
    fn quick_xml_errors_read_in_polish_and_czech_and_as_quick_xml_in_english() {
        let cases = [
            "<?xml version=\"1.0\"?>\n<project><pou></project>",
            "<a><!-- x",
            "<a b=\"1></a>",
            "<a></a></b>",
            "<a",
        ];
        for text in cases {
            let mut reader = Reader::from_str(text);
            let e = loop {
                match reader.read_event() {
                    Err(e) => break e,
                    Ok(Event::Eof) => panic!("{text} reads"),
                    Ok(_) => {}
                }
            };
            let said = reader_said(&e);
            assert_eq!(said.english, e.to_string(), "{text}");
            let polish = said.message.render(Lang::Pl);
            assert_ne!(polish, said.english, "{text}: {polish}");
            assert!(!polish.contains("not found") && !polish.contains("expected"), "{polish}");
        }
        let mut reader = Reader::from_str("<project><pou></project>");
        let e = loop {
            if let Err(e) = reader.read_event() {
                break e;
            }
        };
        assert_eq!(
            reader_said(&e).message.render(Lang::Cs),
            "chybně utvořený dokument: očekáván `</pou>`, ale nalezen `</project>`"
        );
    }
}
