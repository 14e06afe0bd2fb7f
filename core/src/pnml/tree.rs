//! A small owned XML element tree that remembers where each element starts, so that PNML
//! errors can name a line and column (quick-xml's event reader underneath; namespace
//! prefixes are dropped).

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

use super::PnmlError;
use crate::diagnostics::LineIndex;
use crate::limits::MAX_XML_DEPTH;
use crate::msg;

/// One XML element.
#[derive(Debug, Clone, Default)]
pub(super) struct Element {
    /// Local name.
    pub name: String,
    /// Attributes by local name.
    pub attrs: Vec<(String, String)>,
    /// Child elements in document order.
    pub children: Vec<Element>,
    /// Character data directly inside.
    pub text: String,
    /// Byte offset of the start tag.
    pub offset: usize,
}

impl Element {
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attrs.iter().find(|(k, _)| k == name).map(|(_, v)| v.as_str())
    }

    pub fn child(&self, name: &str) -> Option<&Element> {
        self.children.iter().find(|c| c.name == name)
    }

    pub fn children_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Element> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }

    /// The text of the `<text>` child of child `name` (PNML's annotation shape).
    pub fn annotation(&self, name: &str) -> Option<&str> {
        self.child(name)?.child("text").map(|t| t.text.as_str())
    }
}

fn start(e: &BytesStart<'_>, offset: usize, index: &LineIndex<'_>) -> Result<Element, PnmlError> {
    let name = e.local_name().as_ref().to_string();
    let mut attrs = Vec::new();
    for a in e.attributes() {
        let a = a.map_err(|err| {
            let error = err.to_string();
            PnmlError::at(index, offset, msg!(PnmlBadAttribute, element = name, error = error))
        })?;
        let key = a.key.local_name().as_ref().to_string();
        let value = a
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|err| {
                let error = err.to_string();
                let said =
                    msg!(PnmlBadAttributeValue, attribute = key, element = name, error = error);
                PnmlError::at(index, offset, said)
            })?
            .into_owned();
        attrs.push((key, value));
    }
    Ok(Element { name, attrs, children: Vec::new(), text: String::new(), offset })
}

/// Parses a document into its root element.
pub(super) fn parse(xml: &str) -> Result<Element, PnmlError> {
    let index = LineIndex::new(xml);
    let mut reader = Reader::from_str(xml);
    let mut stack: Vec<Element> = Vec::new();
    let mut root: Option<Element> = None;
    loop {
        let offset = reader.buffer_position() as usize;
        let event = reader.read_event().map_err(|e| {
            let said = msg!(PnmlMalformedXml, error = crate::plcopen::reader_said(&e));
            PnmlError::at(&index, reader.buffer_position() as usize, said)
        })?;
        let finished = match event {
            Event::Start(e) => {
                if stack.len() >= MAX_XML_DEPTH {
                    let said = msg!(PnmlTooDeep, depth = MAX_XML_DEPTH);
                    return Err(PnmlError::at(&index, offset, said));
                }
                stack.push(start(&e, offset, &index)?);
                None
            }
            Event::Empty(e) => Some(start(&e, offset, &index)?),
            Event::End(_) => Some(
                stack
                    .pop()
                    .ok_or_else(|| PnmlError::at(&index, offset, msg!(PnmlEndWithoutStart)))?,
            ),
            Event::Text(t) => {
                if let Some(top) = stack.last_mut() {
                    top.text.push_str(&t.xml10_content());
                }
                None
            }
            Event::CData(t) => {
                if let Some(top) = stack.last_mut() {
                    top.text.push_str(&t.into_inner());
                }
                None
            }
            Event::GeneralRef(r) => {
                let resolved = match r.resolve_char_ref() {
                    Ok(Some(c)) => c.to_string(),
                    _ => {
                        let name = r.into_inner().into_owned();
                        quick_xml::escape::resolve_predefined_entity(&name)
                            .ok_or_else(|| {
                                PnmlError::at(&index, offset, msg!(PnmlUnknownEntity, name = name))
                            })?
                            .to_string()
                    }
                };
                if let Some(top) = stack.last_mut() {
                    top.text.push_str(&resolved);
                }
                None
            }
            Event::Eof => break,
            _ => None,
        };
        if let Some(node) = finished {
            match stack.last_mut() {
                Some(parent) => parent.children.push(node),
                None if root.is_none() => root = Some(node),
                None => return Err(PnmlError::at(&index, offset, msg!(PnmlSecondRoot))),
            }
        }
    }
    if let Some(open) = stack.last() {
        let said = msg!(PnmlNeverClosed, element = open.name);
        return Err(PnmlError::at(&index, open.offset, said));
    }
    root.ok_or_else(|| PnmlError::at(&index, 0, msg!(PnmlNoElement)))
}
