//! Share links: a project compressed (DEFLATE, miniz_oxide) and base64url-encoded into
//! the URL fragment, so no server is involved.

use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use base64::Engine;
use std::fmt;

use super::{Project, ProjectError};
use crate::diagnostics::Said;

/// The fragment prefix of a share link: `#p=<data>`.
pub const SHARE_PREFIX: &str = "p=";

use crate::limits::MAX_PROJECT_BYTES;

/// Why a share link could not be opened.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ShareError {
    /// The fragment does not start with `p=`.
    NotAShareLink,
    /// The data is not base64url.
    BadEncoding,
    /// The data does not decompress (truncated or altered link).
    BadCompression,
    /// The decompressed data is not a project.
    BadProject(ProjectError),
}

impl ShareError {
    /// The error as a message, with its English text (what it displays as).
    pub fn said(&self) -> Said {
        match self {
            ShareError::NotAShareLink => crate::msg!(ShareNotALink),
            ShareError::BadEncoding | ShareError::BadCompression => crate::msg!(ShareDamaged),
            ShareError::BadProject(e) => crate::msg!(ShareBadProject, error = e.said()),
        }
    }
}

impl fmt::Display for ShareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.said().english)
    }
}

impl std::error::Error for ShareError {}

/// Encodes a project as a URL fragment (without `#`): `p=<base64url(deflate(json))>`.
pub fn encode_share(project: &Project) -> String {
    let json = serde_json::to_vec(project).unwrap_or_default();
    format!("{SHARE_PREFIX}{}", pack(&json))
}

/// Decodes a URL fragment (with or without `#`) made by [`encode_share`].
pub fn decode_share(fragment: &str) -> Result<Project, ShareError> {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    let data = fragment.strip_prefix(SHARE_PREFIX).ok_or(ShareError::NotAShareLink)?;
    let text = unpack(data)?;
    Project::from_file(&text).map_err(ShareError::BadProject)
}

/// Text compressed for a link: base64url of its DEFLATE.
pub fn pack(bytes: &[u8]) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(bytes, 9))
}

/// The text [`pack`] packed, at most [`MAX_PROJECT_BYTES`] long.
pub fn unpack(data: &str) -> Result<String, ShareError> {
    let packed = URL_SAFE_NO_PAD.decode(data.trim()).map_err(|_| ShareError::BadEncoding)?;
    let bytes = miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_PROJECT_BYTES)
        .map_err(|_| ShareError::BadCompression)?;
    String::from_utf8(bytes).map_err(|_| ShareError::BadCompression)
}
