//! ZIP archives (PKWARE APPNOTE 6.3, the subset every unzipper and LMS reads): files
//! DEFLATE-compressed with miniz_oxide (the share links' compressor) or stored when that
//! does not make them smaller, CRC-32 checked, UTF-8 names, one fixed time stamp so the
//! same files give the same archive. No ZIP64: an archive over 4 GiB, or of more than
//! 65,535 files, is refused. Written here rather than with the `zip` crate: its current
//! releases need a newer Rust than this workspace's, and the same writer runs natively
//! (`plc exercise scorm`) and in the exercise worker (the page's `Export SCORM package`).

/// The archive's time stamp: 1 January 2000, 00:00 (MS-DOS date and time fields).
const DOS_DATE: u16 = ((2000 - 1980) << 9) | (1 << 5) | 1;
const DOS_TIME: u16 = 0;

/// "Version needed to extract": 2.0 (DEFLATE); "made by": 2.0 on Unix (`3 << 8`).
const VERSION_NEEDED: u16 = 20;
const VERSION_MADE_BY: u16 = (3 << 8) | 20;
/// General-purpose flag bit 11: the name is UTF-8.
const UTF8_NAMES: u16 = 1 << 11;

/// The CRC-32 (IEEE 802.3, reflected, as ZIP and gzip use it) of `bytes`.
pub fn crc32(bytes: &[u8]) -> u32 {
    const fn table() -> [u32; 256] {
        let mut table = [0u32; 256];
        let mut n = 0;
        while n < 256 {
            let mut c = n as u32;
            let mut k = 0;
            while k < 8 {
                c = if c & 1 != 0 { 0xEDB8_8320 ^ (c >> 1) } else { c >> 1 };
                k += 1;
            }
            table[n] = c;
            n += 1;
        }
        table
    }
    const TABLE: [u32; 256] = table();
    !bytes.iter().fold(!0u32, |c, &b| TABLE[((c ^ u32::from(b)) & 0xFF) as usize] ^ (c >> 8))
}

/// Why an archive could not be written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ZipError(pub String);

impl std::fmt::Display for ZipError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ZipError {}

fn u16_le(out: &mut Vec<u8>, v: u16) {
    out.extend_from_slice(&v.to_le_bytes());
}

fn u32_le(out: &mut Vec<u8>, v: u32) {
    out.extend_from_slice(&v.to_le_bytes());
}

/// A ZIP archive of `files` (`(path, contents)`, paths with `/` between folders), in the
/// order given.
pub fn zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, ZipError> {
    let too_big = || ZipError("the archive would be over 4 GiB (ZIP64 is not written)".into());
    let count = u16::try_from(files.len())
        .map_err(|_| ZipError(format!("{} files are more than a ZIP holds", files.len())))?;
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (path, data) in files {
        let name = path.trim_start_matches('/').as_bytes();
        let name_len = u16::try_from(name.len())
            .map_err(|_| ZipError(format!("the file name {path} is too long")))?;
        let crc = crc32(data);
        let deflated = miniz_oxide::deflate::compress_to_vec(data, 9);
        let (method, body): (u16, &[u8]) =
            if deflated.len() < data.len() { (8, &deflated) } else { (0, data) };
        let size = u32::try_from(data.len()).map_err(|_| too_big())?;
        let packed = u32::try_from(body.len()).map_err(|_| too_big())?;
        let offset = u32::try_from(out.len()).map_err(|_| too_big())?;
        // The local file header, then the data.
        u32_le(&mut out, 0x0403_4b50);
        u16_le(&mut out, VERSION_NEEDED);
        u16_le(&mut out, UTF8_NAMES);
        u16_le(&mut out, method);
        u16_le(&mut out, DOS_TIME);
        u16_le(&mut out, DOS_DATE);
        u32_le(&mut out, crc);
        u32_le(&mut out, packed);
        u32_le(&mut out, size);
        u16_le(&mut out, name_len);
        u16_le(&mut out, 0);
        out.extend_from_slice(name);
        out.extend_from_slice(body);
        // Its entry in the central directory.
        u32_le(&mut central, 0x0201_4b50);
        u16_le(&mut central, VERSION_MADE_BY);
        u16_le(&mut central, VERSION_NEEDED);
        u16_le(&mut central, UTF8_NAMES);
        u16_le(&mut central, method);
        u16_le(&mut central, DOS_TIME);
        u16_le(&mut central, DOS_DATE);
        u32_le(&mut central, crc);
        u32_le(&mut central, packed);
        u32_le(&mut central, size);
        u16_le(&mut central, name_len);
        u16_le(&mut central, 0); // extra field
        u16_le(&mut central, 0); // comment
        u16_le(&mut central, 0); // disk
        u16_le(&mut central, 0); // internal attributes
        u32_le(&mut central, 0o100_644 << 16); // a regular file, rw-r--r--
        u32_le(&mut central, offset);
        central.extend_from_slice(name);
    }
    let central_at = u32::try_from(out.len()).map_err(|_| too_big())?;
    let central_len = u32::try_from(central.len()).map_err(|_| too_big())?;
    out.extend_from_slice(&central);
    // The end of central directory record.
    u32_le(&mut out, 0x0605_4b50);
    u16_le(&mut out, 0);
    u16_le(&mut out, 0);
    u16_le(&mut out, count);
    u16_le(&mut out, count);
    u32_le(&mut out, central_len);
    u32_le(&mut out, central_at);
    u16_le(&mut out, 0);
    u32::try_from(out.len()).map_err(|_| too_big())?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn u16_at(b: &[u8], at: usize) -> u16 {
        u16::from_le_bytes([b[at], b[at + 1]])
    }

    fn u32_at(b: &[u8], at: usize) -> u32 {
        u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
    }

    /// Reads an archive back through its central directory, as an unzipper does: every
    /// file's name and contents, each checked against its CRC-32.
    fn unzip(b: &[u8]) -> Vec<(String, Vec<u8>)> {
        let end = b.len() - 22;
        assert_eq!(u32_at(b, end), 0x0605_4b50);
        let count = usize::from(u16_at(b, end + 10));
        let mut at = u32_at(b, end + 16) as usize;
        let mut files = Vec::new();
        for _ in 0..count {
            assert_eq!(u32_at(b, at), 0x0201_4b50);
            let method = u16_at(b, at + 10);
            let crc = u32_at(b, at + 16);
            let packed = u32_at(b, at + 20) as usize;
            let size = u32_at(b, at + 24) as usize;
            let name_len = usize::from(u16_at(b, at + 28));
            let local = u32_at(b, at + 42) as usize;
            let name = String::from_utf8(b[at + 46..at + 46 + name_len].to_vec()).unwrap();
            assert_eq!(u32_at(b, local), 0x0403_4b50);
            let start = local + 30 + usize::from(u16_at(b, local + 26));
            let body = &b[start..start + packed];
            let data = match method {
                0 => body.to_vec(),
                8 => miniz_oxide::inflate::decompress_to_vec(body).unwrap(),
                m => panic!("method {m}"),
            };
            assert_eq!((data.len(), crc32(&data)), (size, crc), "{name}");
            files.push((name, data));
            at += 46 + name_len;
        }
        files
    }

    #[test]
    fn the_crc_is_the_standard_one() {
        assert_eq!(crc32(b""), 0);
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn an_archive_reads_back_with_every_file() {
        let files = vec![
            ("index.html".to_string(), b"<!DOCTYPE html>".repeat(50)),
            ("exercise/latch.toml".to_string(), "id = \"latch\" # ü".as_bytes().to_vec()),
            ("empty".to_string(), Vec::new()),
            ("noise.bin".to_string(), (0..=255u8).collect()),
        ];
        let archive = zip(&files).unwrap();
        assert_eq!(unzip(&archive), files);
        // Compressed when that pays, stored otherwise; the same files, the same bytes.
        assert!(archive.len() < 750 + 300, "{}", archive.len());
        assert_eq!(zip(&files).unwrap(), archive);
    }
}
