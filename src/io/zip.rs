//! A zip archive of files stored as they are (no compression: the PDFs inside are already
//! compressed, and the text files are small), for the browser, where an exercise set leaves
//! as one download. The format is PKWARE's APPNOTE (local headers, the central directory,
//! its end record); the CRC-32 is crc32fast's. Nothing depends on the clock: every entry is
//! dated 1980-01-01, so the same files give the same bytes.

/// The zip archive holding `files` (names with `/` for folders, each under 4 GiB).
pub fn zip_stored(files: &[(String, Vec<u8>)]) -> Vec<u8> {
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (name, bytes) in files {
        let crc = crc32fast::hash(bytes);
        let size = bytes.len() as u32;
        let offset = out.len() as u32;
        let name = name.as_bytes();
        // The local file header.
        out.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
        out.extend_from_slice(&20u16.to_le_bytes()); // version needed: 2.0
        out.extend_from_slice(&0x0800u16.to_le_bytes()); // flags: UTF-8 names
        out.extend_from_slice(&0u16.to_le_bytes()); // stored
        out.extend_from_slice(&0u16.to_le_bytes()); // time 00:00
        out.extend_from_slice(&0x0021u16.to_le_bytes()); // date 1980-01-01
        out.extend_from_slice(&crc.to_le_bytes());
        out.extend_from_slice(&size.to_le_bytes());
        out.extend_from_slice(&size.to_le_bytes());
        out.extend_from_slice(&(name.len() as u16).to_le_bytes());
        out.extend_from_slice(&0u16.to_le_bytes());
        out.extend_from_slice(name);
        out.extend_from_slice(bytes);
        // Its entry in the central directory.
        central.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
        central.extend_from_slice(&20u16.to_le_bytes()); // made by: 2.0
        central.extend_from_slice(&20u16.to_le_bytes());
        central.extend_from_slice(&0x0800u16.to_le_bytes());
        central.extend_from_slice(&0u16.to_le_bytes());
        central.extend_from_slice(&0u16.to_le_bytes());
        central.extend_from_slice(&0x0021u16.to_le_bytes());
        central.extend_from_slice(&crc.to_le_bytes());
        central.extend_from_slice(&size.to_le_bytes());
        central.extend_from_slice(&size.to_le_bytes());
        central.extend_from_slice(&(name.len() as u16).to_le_bytes());
        central.extend_from_slice(&[0; 8]); // extra, comment, disk, internal attributes
        central.extend_from_slice(&0u32.to_le_bytes()); // external attributes
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name);
    }
    let (start, length) = (out.len() as u32, central.len() as u32);
    out.extend_from_slice(&central);
    out.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
    out.extend_from_slice(&[0; 4]); // this disk, the directory's disk
    out.extend_from_slice(&(files.len() as u16).to_le_bytes());
    out.extend_from_slice(&(files.len() as u16).to_le_bytes());
    out.extend_from_slice(&length.to_le_bytes());
    out.extend_from_slice(&start.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    out
}

#[cfg(test)]
mod tests {
    #[cfg(unix)]
    use super::*;

    #[test]
    #[cfg(unix)] // Python's zipfile reads the zip back: no python3 on Windows (Wine)
    fn unzip_reads_back_every_file() {
        let files = vec![
            ("exercício-01.md".to_string(), "# exercício 1\nI = [0,5 0,25 0 0]\n".as_bytes().to_vec()),
            ("sheets.pdf".to_string(), (0..5000u32).map(|i| (i * 7 % 251) as u8).collect()),
            ("empty.txt".to_string(), Vec::new()),
        ];
        let zip = zip_stored(&files);
        assert_eq!(zip, zip_stored(&files), "the same files, the same bytes");
        let dir = std::env::temp_dir().join(format!("phonglab-zip-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("set.zip"), &zip).unwrap();
        // Python's zipfile checks the CRCs and the directory (the system's unzip may be absent).
        let out = std::process::Command::new("python3")
            .args(["-c", "import sys, zipfile; z = zipfile.ZipFile(sys.argv[1]); assert z.testzip() is None; z.extractall(sys.argv[2]); print(len(z.namelist()))"])
            .arg(dir.join("set.zip"))
            .arg(dir.join("out"))
            .output()
            .expect("python3 runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), "3");
        for (name, bytes) in &files {
            assert_eq!(&std::fs::read(dir.join("out").join(name)).unwrap(), bytes, "{name}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
