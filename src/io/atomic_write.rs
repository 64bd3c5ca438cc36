//! Every file phonglab writes is written whole or not at all: the one way to write a file
//! is the core's ([`phonglab_core::files::atomic_write`]), which the command line, the
//! window and the Python package share; its tests are here, beside the sets of files
//! ([`super::file_set`]) built on its steps.

pub use phonglab_core::files::atomic_write::*;

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use std::path::{Path, PathBuf};

    /// [`temp_dir`], named once more by the time: for a test that plants links, whose folder
    /// an earlier run may have left (Wine reuses process numbers, and its `remove_dir_all`
    /// follows a Unix link), so that no run meets another's.
    pub(crate) fn fresh_dir(name: &str) -> PathBuf {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).unwrap_or_default().as_nanos();
        temp_dir(&format!("{name}-{nanos}"))
    }

    pub(crate) fn temp_dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("phonglab-atomic-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    pub(crate) fn listing(dir: &Path) -> Vec<(String, Vec<u8>)> {
        let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| {
                let e = e.unwrap();
                let bytes = if e.path().is_file() { std::fs::read(e.path()).unwrap() } else { b"<dir>".to_vec() };
                (e.file_name().to_string_lossy().into_owned(), bytes)
            })
            .collect();
        v.sort();
        v
    }

    /// Windows: lets everyone write the file or folder at `path` (its DACL: Everyone, full
    /// control), as Wine makes it from the Unix mode a teacher's umask 000 gives (0666, 0777).
    #[cfg(windows)]
    pub(crate) fn everyone_may_write(path: &Path) {
        use std::os::windows::ffi::OsStrExt;
        use windows_sys::Win32::Security::{
            ACL, ACL_REVISION, AddAccessAllowedAceEx, CreateWellKnownSid, DACL_SECURITY_INFORMATION, InitializeAcl,
            InitializeSecurityDescriptor, SetFileSecurityW, SetSecurityDescriptorDacl, WinWorldSid,
        };
        use windows_sys::Win32::Storage::FileSystem::FILE_ALL_ACCESS;
        let (mut sid, mut acl, mut sd) = ([0u64; 16], [0u64; 32], [0u64; 8]);
        let mut sid_len = 128u32;
        let wide: Vec<u16> = path.as_os_str().encode_wide().chain([0]).collect();
        // SAFETY: each buffer is as large as the call is told; the path is NUL-terminated.
        let done = unsafe {
            CreateWellKnownSid(WinWorldSid, std::ptr::null_mut(), sid.as_mut_ptr().cast(), &mut sid_len) != 0
                && InitializeAcl(acl.as_mut_ptr().cast::<ACL>(), 256, ACL_REVISION) != 0
                && AddAccessAllowedAceEx(
                    acl.as_mut_ptr().cast(),
                    ACL_REVISION,
                    0,
                    FILE_ALL_ACCESS,
                    sid.as_mut_ptr().cast(),
                ) != 0
                && InitializeSecurityDescriptor(sd.as_mut_ptr().cast(), 1) != 0
                && SetSecurityDescriptorDacl(sd.as_mut_ptr().cast(), 1, acl.as_ptr().cast(), 0) != 0
                && SetFileSecurityW(wide.as_ptr(), DACL_SECURITY_INFORMATION, sd.as_mut_ptr().cast()) != 0
        };
        assert!(done, "everyone may write {}: {}", path.display(), std::io::Error::last_os_error());
    }

    /// Makes a symbolic link at `link` to the file `to`, as another process would: `false`
    /// where none can be made (a Windows without the privilege). Windows: Windows' own
    /// (`symlink_file`); under Wine, whose `CreateSymbolicLinkW` makes nothing, a Unix link,
    /// made by the Unix `ln` (Wine starts a Unix program too) at the paths `winepath -u` gives,
    /// and waited for (Wine does not wait for a Unix program).
    pub(crate) fn plant_link(to: &Path, link: &Path) -> bool {
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(to, link).is_ok()
        }
        #[cfg(windows)]
        {
            let unix = |p: &Path| {
                let out = std::process::Command::new("winepath").arg("-u").arg(p).output().ok()?;
                let s = String::from_utf8(out.stdout).ok()?;
                out.status.success().then(|| s.trim_end().to_string())
            };
            if let (Some(to_u), Some(link_u)) = (unix(to), unix(link)) {
                let _ = std::process::Command::new(r"Z:\bin\ln").args(["-s", &to_u, &link_u]).status();
                for _ in 0..500 {
                    if crate::platform::links::reached_through_link(link) {
                        return true;
                    }
                    std::thread::sleep(std::time::Duration::from_millis(20));
                }
                return false;
            }
            std::os::windows::fs::symlink_file(to, link).is_ok() && std::fs::symlink_metadata(link).is_ok()
        }
        #[cfg(not(any(unix, windows)))]
        {
            let _ = (to, link);
            false
        }
    }

    pub(crate) const FAULTS: [Fault; 6] = [
        Fault::AfterBytes(0),
        Fault::AfterBytes(1),
        Fault::AfterBytes(4000),
        Fault::OnSync,
        Fault::OnClose,
        Fault::OnRename(0),
    ];

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let dir = temp_dir("one");
        let target = dir.join("out.png");
        std::fs::write(&target, b"the good old file").unwrap();
        let new = vec![7u8; 10_000];
        for fault in FAULTS {
            let e = with_fault(fault, || write(&target, &new)).unwrap_err();
            assert_eq!(std::fs::read(&target).unwrap(), b"the good old file", "{fault:?}");
            assert_eq!(listing(&dir).len(), 1, "{fault:?}: no temporary left: {:?}", listing(&dir));
            let msg = e.to_string();
            assert!(msg.contains("out.png") && msg.contains("unchanged"), "{msg}");
        }
        write(&target, &new).unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), new);
        assert_eq!(listing(&dir).len(), 1);
    }

    #[test]
    #[cfg(unix)]
    fn a_device_or_a_pipe_is_refused_and_a_link_stays_a_link() {
        // Renaming over /dev/null would turn it into a file for the whole machine, and a
        // FIFO would wait for a reader: both refused, left as they are.
        let e = write(Path::new("/dev/null"), b"x").unwrap_err();
        assert!(e.to_string().contains("not a regular file"), "{e}");
        assert!(check_file_destination(Path::new("/dev/null")).is_err());
        let dir = temp_dir("link");
        let fifo = dir.join("fifo.png");
        let c = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).unwrap();
        // SAFETY: `c` is a valid NUL-terminated path for the duration of the call.
        assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
        assert!(write(&fifo, b"x").unwrap_err().to_string().contains("not a regular file"));
        assert!(check_file_destination(&fifo).is_err());
        std::fs::remove_file(&fifo).unwrap();
        let real = dir.join("real.png");
        std::fs::write(&real, b"old").unwrap();
        let link = dir.join("link.png");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        write(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "still a link");
        assert_eq!(std::fs::read(&real).unwrap(), b"new");
        assert_eq!(listing(&dir).len(), 2, "no temporary left: {:?}", listing(&dir));
    }

    #[test]
    #[cfg(unix)]
    fn a_dangling_link_stays_a_link_and_its_file_is_made() {
        let dir = temp_dir("dangling");
        std::fs::create_dir(dir.join("pictures")).unwrap();
        let link = dir.join("out.png");
        std::os::unix::fs::symlink("pictures/made.png", &link).unwrap();
        check_file_destination(&link).unwrap();
        write(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "still a link");
        assert_eq!(std::fs::read(dir.join("pictures/made.png")).unwrap(), b"new");
        // A loop of links is refused, saying so.
        std::os::unix::fs::symlink("b.png", dir.join("a.png")).unwrap();
        std::os::unix::fs::symlink("a.png", dir.join("b.png")).unwrap();
        assert!(write(&dir.join("a.png"), b"x").unwrap_err().to_string().contains("symbolic links"));
    }

    #[test]
    #[cfg(unix)]
    fn write_here_never_writes_through_a_link() {
        let dir = temp_dir("here");
        let real = dir.join("bashrc");
        std::fs::write(&real, b"mine").unwrap();
        let (link, dangling) = (dir.join("report.md"), dir.join("marks.csv"));
        std::os::unix::fs::symlink("bashrc", &link).unwrap();
        std::os::unix::fs::symlink("made.csv", &dangling).unwrap();
        for l in [&link, &dangling] {
            assert!(write_here(l, b"new").unwrap_err().to_string().contains("not a regular file"));
            assert!(std::fs::symlink_metadata(l).unwrap().file_type().is_symlink(), "left as it was");
        }
        assert_eq!(std::fs::read(&real).unwrap(), b"mine");
        assert!(!dir.join("made.csv").exists());
        assert_eq!(listing(&dir).len(), 3, "no temporary left: {:?}", listing(&dir));
        write_here(&dir.join("plain.md"), b"new").unwrap();
        write_here(&dir.join("plain.md"), b"newer").unwrap();
        assert_eq!(std::fs::read(dir.join("plain.md")).unwrap(), b"newer");
    }

    #[test]
    #[cfg(unix)]
    fn a_killed_writes_temporaries_are_removed_by_the_next_write_of_that_file() {
        let dir = temp_dir("stale");
        // A writer that no longer runs (the largest pid a system gives is below 2^22), one
        // that runs (this one's parent), and this process's own.
        let (dead, alive) = ((1 << 22) + 1, std::os::unix::process::parent_id());
        let stale = format!(".out.png.{dead}.0.tmp");
        let running = format!(".out.png.{alive}.3.tmp");
        let other = format!(".other.png.{dead}.1.tmp");
        for n in [&stale, &running, &other, &".out.png.x.1.tmp".to_string()] {
            std::fs::write(dir.join(n), b"part").unwrap();
        }
        write(&dir.join("out.png"), b"new").unwrap();
        let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
        assert!(!names.contains(&stale), "{names:?}");
        assert!(names.contains(&running) && names.contains(&other), "{names:?}");
        assert!(names.contains(&".out.png.x.1.tmp".to_string()), "not phonglab's form: {names:?}");
    }

    /// Issue 59 (finding 5): a temporary of phonglab's naming whose writer is dead is
    /// removed only when it is provably phonglab's kind of file: a link of that name (to a
    /// file outside; Wine opens it as that file) and, on Unix, a file of another user's
    /// (a classmate's, planted) are left, and the files they name untouched. Under Wine a
    /// killed write's temporary was never removed (every process was taken to run).
    #[test]
    #[cfg(any(unix, windows))]
    fn a_stale_temporary_goes_only_when_provably_phonglabs_own() {
        let dir = fresh_dir("stale-own");
        let outside = fresh_dir("stale-own-outside");
        std::fs::write(outside.join("thesis.txt"), b"mine").unwrap();
        let dead = (1u32 << 22) + 1;
        let (stale, link) = (format!(".out.png.{dead}.0.tmp"), format!(".out.png.{dead}.1.tmp"));
        std::fs::write(dir.join(&stale), b"part").unwrap();
        let linked = plant_link(&outside.join("thesis.txt"), &dir.join(&link));
        // A classmate's file of phonglab's naming (Unix, where this test may give it away).
        let theirs = format!(".out.png.{dead}.2.tmp");
        std::fs::write(dir.join(&theirs), b"theirs").unwrap();
        #[cfg(unix)]
        let given_away = std::os::unix::fs::chown(dir.join(&theirs), Some(54_321), None).is_ok();
        #[cfg(windows)]
        let given_away = false;
        if !given_away {
            std::fs::remove_file(dir.join(&theirs)).unwrap();
        }
        write(&dir.join("out.png"), b"new").unwrap();
        let names: Vec<String> = listing(&dir).into_iter().map(|(n, _)| n).collect();
        assert!(!names.contains(&stale), "the dead writer's temporary is removed: {names:?}");
        assert_eq!(names.contains(&link), linked, "a link is left: {names:?}");
        assert_eq!(names.contains(&theirs), given_away, "another user's file is left: {names:?}");
        assert_eq!(std::fs::read(outside.join("thesis.txt")).unwrap(), b"mine");
    }

    #[test]
    #[cfg(unix)]
    fn a_replaced_file_keeps_its_permissions() {
        use std::os::unix::fs::PermissionsExt;
        let dir = temp_dir("mode");
        let private = dir.join("private.toml");
        std::fs::write(&private, b"old").unwrap();
        std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o600)).unwrap();
        write(&private, b"new").unwrap();
        assert_eq!(std::fs::metadata(&private).unwrap().permissions().mode() & 0o777, 0o600);
        std::fs::set_permissions(&private, std::fs::Permissions::from_mode(0o640)).unwrap();
        write(&private, b"newer").unwrap();
        assert_eq!(std::fs::metadata(&private).unwrap().permissions().mode() & 0o777, 0o640);
        assert_eq!(std::fs::read(&private).unwrap(), b"newer");
    }

    #[test]
    fn the_injected_fault_names_the_failing_step() {
        let dir = temp_dir("steps");
        let t = dir.join("a.txt");
        let step = |f| with_fault(f, || write(&t, b"abc")).unwrap_err().what;
        assert_eq!(step(Fault::AfterBytes(2)), "write-step-write");
        assert_eq!(step(Fault::OnSync), "write-step-sync");
        assert_eq!(step(Fault::OnClose), "write-step-close");
        assert_eq!(step(Fault::OnRename(0)), "write-step-rename");
        assert!(!t.exists(), "nothing was there, and nothing is");
    }

    #[test]
    fn a_folder_or_a_missing_folder_is_refused_before_work() {
        let dir = temp_dir("dest");
        assert!(check_file_destination(&dir).is_err(), "a folder is not a file");
        assert!(check_file_destination(&dir.join("missing/out.png")).is_err());
        check_file_destination(&dir.join("out.png")).unwrap();
        check_folder_destination(&dir.join("new/deeper")).unwrap();
        std::fs::write(dir.join("plain"), b"x").unwrap();
        assert!(check_folder_destination(&dir.join("plain")).is_err(), "a file is not a folder");
        assert!(check_folder_destination(Path::new("/proc/phonglab-cannot-be-here")).is_err());
        assert_eq!(listing(&dir).iter().filter(|(n, _)| n.ends_with(".tmp")).count(), 0);
    }
}
