//! The system's reasons for a failed read or write, said in the user's language: the
//! common kinds (a missing file, no permission, a full disk) from the catalogue, any
//! other as the system says it.

use std::io;

use crate::t;

/// A path as a message shows it: its control characters (an escape sequence, a line break,
/// a right-to-left override in a file's name) written visibly, `\u{1B}`, so that naming a
/// file never sends anything to the terminal but its name.
pub fn shown(path: &std::path::Path) -> String {
    crate::formats::escape::terminal::text(&path.display().to_string())
}

/// Why `e` happened, for a person.
pub fn io_reason(e: &io::Error) -> String {
    use io::ErrorKind as K;
    match e.kind() {
        K::NotFound => t!("io-not-found"),
        K::PermissionDenied => t!("io-permission-denied"),
        K::StorageFull | K::QuotaExceeded => t!("io-storage-full"),
        K::IsADirectory => t!("io-is-a-directory"),
        K::NotADirectory => t!("io-not-a-directory"),
        K::ReadOnlyFilesystem => t!("io-read-only"),
        K::AlreadyExists => t!("io-already-exists"),
        K::InvalidFilename => t!("io-invalid-name"),
        K::ResourceBusy => t!("io-open-elsewhere"),
        // Windows (Wine): a handle phonglab holds, lost because a Unix program renamed the
        // folder it is in ("Invalid handle. (os error 6)"), and a link refused or changed
        // while phonglab wrote ("The filename cannot be resolved. (os error 1921)").
        _ if cfg!(windows) && e.raw_os_error() == Some(6) => t!("io-handle-lost"),
        _ if cfg!(windows) && e.raw_os_error() == Some(1921) => t!("io-link-in-the-way"),
        _ => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::locale::{Lang, Locale, with_locale};

    #[test]
    fn common_reasons_are_said_in_the_language() {
        let missing = std::fs::read("/no/such/phonglab/file").unwrap_err();
        assert_eq!(with_locale(Locale::of(Lang::PtPt), || io_reason(&missing)), "não existe");
        assert_eq!(with_locale(Locale::of(Lang::En), || io_reason(&missing)), "it does not exist");
        let full = io::Error::new(io::ErrorKind::StorageFull, "no space left on device");
        assert_eq!(with_locale(Locale::of(Lang::PtBr), || io_reason(&full)), "o disco está cheio");
        // Another kind: the system's own words.
        let other = io::Error::other("something odd");
        assert_eq!(with_locale(Locale::of(Lang::PtPt), || io_reason(&other)), "something odd");
        // Windows (Wine, issue 59, round 3): a handle lost to a folder renamed by a Unix
        // program, a link in the way, in words, not "os error 6" or "1921".
        if cfg!(windows) {
            let lost = with_locale(Locale::of(Lang::En), || io_reason(&io::Error::from_raw_os_error(6)));
            assert!(lost.contains("renamed or replaced by a link") && !lost.contains("os error"), "{lost}");
            let link = with_locale(Locale::of(Lang::PtBr), || io_reason(&io::Error::from_raw_os_error(1921)));
            assert!(link.contains("link no caminho") && !link.contains("os error"), "{link}");
        }
    }
}
