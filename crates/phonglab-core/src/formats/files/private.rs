//! Files and folders of this user's alone: phonglab's records (a set's list of what it
//! wrote, a journal, the list of what was staged) and its working folders, made so that no
//! one else may write them, and trusted later only while that is still so (issue 59: a
//! classmate can write a record in phonglab's exact form, but not as the teacher).
//!
//! - Unix: made 0600 and 0700 whatever the umask (`platform::held_dir`); trusted when owned
//!   by the process's effective user and writable by no group and no other user.
//! - Windows: made with an owner-only security descriptor (`OwnerOnly`: this user the
//!   owner, and a protected DACL with one entry, this user's SID with full control,
//!   inherited by nothing and inheriting nothing); trusted when its owner is this user and
//!   its DACL lets no one else write it ([`is_this_users_alone`]). Before, only the owner
//!   was asked, and a teacher's umask 000 (a lab share) let Wine give everyone write in
//!   the DACL it maps from the Unix mode: a classmate rewrote the teacher's own list in
//!   place, and the next run deleted her files (issue 59, round 3).

use std::fs::File;

/// Is the open `file` this user's alone, so that phonglab may trust what it says it wrote
/// there (a set's records: its list of what it wrote, a journal, a staging folder)? Unix:
/// owned by the process's effective user and writable by no group or other user. Windows:
/// owned by this user (the token's user or its default owner; under Wine a Unix file of
/// another user's is owned by "ANONYMOUS LOGON"), and its DACL, read through the handle,
/// grants write (any of write data, append, write attributes or extended attributes,
/// delete, delete a child, change the DACL or the owner, generic write or all) to no SID
/// but the owner's, this user's, SYSTEM's and the Administrators' (the system itself and
/// those who can take any file's ownership anyway: an entry for them gives them nothing
/// they lack). No DACL at all (everyone may do anything), or an entry of a kind not read
/// here that allows, is not trusted. `false` where the system cannot say.
pub fn is_this_users_alone(file: &File) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        // SAFETY: geteuid only reads the process's user.
        file.metadata().is_ok_and(|m| m.uid() == unsafe { libc::geteuid() } && m.mode() & 0o022 == 0)
    }
    #[cfg(windows)]
    {
        windows::owned_by_this_user(file) && windows::writable_by_no_one_else(file)
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = file;
        false
    }
}

/// Is the open `file` owned by this process's user (Unix: its effective user; Windows: the
/// token's user or default owner)? `false` where the system cannot say.
pub fn is_owned_by_this_user(file: &File) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        // SAFETY: geteuid only reads the process's user.
        file.metadata().is_ok_and(|m| m.uid() == unsafe { libc::geteuid() })
    }
    #[cfg(windows)]
    {
        windows::owned_by_this_user(file)
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = file;
        false
    }
}

#[cfg(windows)]
pub use windows::{OwnerOnly, create_dir, make_owner_only};

#[cfg(windows)]
mod windows {
    use std::fs::File;
    use std::io;
    use std::os::windows::io::AsRawHandle;
    use std::path::Path;

    use windows_sys::Win32::Foundation::{CloseHandle, HANDLE};
    use windows_sys::Win32::Security::{
        ACCESS_ALLOWED_ACE, ACE_HEADER, ACL, ACL_REVISION_DS, AddAccessAllowedAceEx, AddAce, CONTAINER_INHERIT_ACE,
        DACL_SECURITY_INFORMATION, EqualSid, GetAce, GetKernelObjectSecurity, GetLengthSid, GetSecurityDescriptorDacl,
        GetSecurityDescriptorOwner, GetTokenInformation, INHERIT_ONLY_ACE, INHERITED_ACE, InitializeAcl,
        InitializeSecurityDescriptor, IsWellKnownSid, OBJECT_INHERIT_ACE, OWNER_SECURITY_INFORMATION,
        PROTECTED_DACL_SECURITY_INFORMATION, PSID, SE_DACL_PROTECTED, SECURITY_ATTRIBUTES, SetFileSecurityW,
        SetSecurityDescriptorControl, SetSecurityDescriptorDacl, SetSecurityDescriptorOwner, TOKEN_INFORMATION_CLASS,
        TOKEN_OWNER, TOKEN_QUERY, TOKEN_USER, TokenOwner, TokenUser, WinBuiltinAdministratorsSid, WinLocalSystemSid,
    };
    use windows_sys::Win32::Storage::FileSystem::{CreateDirectoryW, FILE_ALL_ACCESS, FILE_EXECUTE};
    use windows_sys::Win32::System::Threading::{GetCurrentProcess, OpenProcessToken};

    /// The rights that change a file or folder: write data (a folder: add a file), append
    /// (add a folder), write extended attributes, delete a child, write attributes, delete,
    /// write the DACL, write the owner, generic all, generic write.
    const WRITE_RIGHTS: u32 =
        0x2 | 0x4 | 0x10 | 0x40 | 0x100 | 0x1_0000 | 0x4_0000 | 0x8_0000 | 0x1000_0000 | 0x4000_0000;
    /// `ACCESS_ALLOWED_ACE_TYPE`.
    const ALLOWED: u8 = 0;
    /// The entries that deny (`ACCESS_DENIED_ACE_TYPE`, its object and callback forms) and
    /// those of a SACL (audit, alarm): none gives anyone the right to write.
    const NOT_ALLOWING: [u8; 10] = [1, 2, 3, 6, 7, 8, 10, 12, 13, 15];
    /// `SECURITY_DESCRIPTOR_REVISION`.
    const SD_REVISION: u32 = 1;

    /// A buffer of u64s (aligned for what the call writes) that `call(buf, len, &mut need)`
    /// fills, asked once for its size.
    fn filled(call: &dyn Fn(*mut core::ffi::c_void, u32, &mut u32) -> i32) -> Option<Vec<u64>> {
        let mut need = 0u32;
        call(std::ptr::null_mut(), 0, &mut need);
        if need == 0 {
            return None;
        }
        let mut buf = vec![0u64; (need as usize).div_ceil(8)];
        (call(buf.as_mut_ptr().cast(), need, &mut need) != 0).then_some(buf)
    }

    /// This process's user, as its token says: its SID and the default owner of what it
    /// makes (an elevated administrator's: the Administrators group), each in the buffer
    /// the token wrote it into.
    struct Token {
        user: Vec<u64>,
        owner: Option<Vec<u64>>,
    }

    impl Token {
        fn of_process() -> Option<Token> {
            let mut token: HANDLE = std::ptr::null_mut();
            // SAFETY: the process's own pseudo-handle; `token` is written, closed below.
            if unsafe { OpenProcessToken(GetCurrentProcess(), TOKEN_QUERY, &mut token) } == 0 {
                return None;
            }
            let of_token = |class: TOKEN_INFORMATION_CLASS| {
                // SAFETY: `token` is open through the call; the buffer holds `len` bytes.
                filled(&|buf, len, need| unsafe { GetTokenInformation(token, class, buf, len, need) })
            };
            let (user, owner) = (of_token(TokenUser), of_token(TokenOwner));
            // SAFETY: closed once.
            unsafe { CloseHandle(token) };
            Some(Token { user: user?, owner })
        }

        fn user(&self) -> PSID {
            // SAFETY: the buffer holds the TOKEN_USER the token wrote, whose SID points
            // into the same buffer, alive as long as `self`.
            unsafe { (*self.user.as_ptr().cast::<TOKEN_USER>()).User.Sid }
        }

        fn default_owner(&self) -> PSID {
            // SAFETY: as in `user`, for a TOKEN_OWNER.
            self.owner.as_ref().map_or(std::ptr::null_mut(), |b| unsafe { (*b.as_ptr().cast::<TOKEN_OWNER>()).Owner })
        }

        /// Is `sid` this user's (the token's user or default owner)?
        fn is_mine(&self, sid: PSID) -> bool {
            // SAFETY: both SIDs are valid while `self` and the caller's buffer live.
            let same = |mine: PSID| !mine.is_null() && unsafe { EqualSid(sid, mine) } != 0;
            same(self.user()) || same(self.default_owner())
        }
    }

    /// The security descriptor of the open `file` (what `info` asks), read through its handle.
    fn security_of(file: &File, info: u32) -> Option<Vec<u64>> {
        let handle = file.as_raw_handle();
        // SAFETY: the handle is open (with READ_CONTROL) through the call; the buffer holds
        // `len` bytes.
        filled(&|buf, len, need| unsafe { GetKernelObjectSecurity(handle, info, buf, len, need) })
    }

    /// The owner's SID in the security descriptor `sd` (pointing into it).
    fn owner_in(sd: &[u64]) -> Option<PSID> {
        let (mut owner, mut defaulted): (PSID, i32) = (std::ptr::null_mut(), 0);
        // SAFETY: `sd` is a security descriptor the system wrote; `owner` points into it.
        let ok = unsafe { GetSecurityDescriptorOwner(sd.as_ptr().cast_mut().cast(), &mut owner, &mut defaulted) };
        (ok != 0 && !owner.is_null()).then_some(owner)
    }

    /// Is the open `file` owned by this process's user (see [`super::is_owned_by_this_user`])?
    pub fn owned_by_this_user(file: &File) -> bool {
        let (Some(sd), Some(token)) = (security_of(file, OWNER_SECURITY_INFORMATION), Token::of_process()) else {
            return false;
        };
        owner_in(&sd).is_some_and(|owner| token.is_mine(owner))
    }

    /// Does the DACL of the open `file` grant write to no SID but its owner's, this user's,
    /// SYSTEM's and the Administrators' (see [`super::is_this_users_alone`])?
    pub fn writable_by_no_one_else(file: &File) -> bool {
        let (Some(sd), Some(token)) =
            (security_of(file, OWNER_SECURITY_INFORMATION | DACL_SECURITY_INFORMATION), Token::of_process())
        else {
            return false;
        };
        let Some(owner) = owner_in(&sd) else { return false };
        let (mut present, mut dacl, mut defaulted): (i32, *mut ACL, i32) = (0, std::ptr::null_mut(), 0);
        // SAFETY: `sd` is the security descriptor just read; `dacl` points into it.
        let read = unsafe {
            GetSecurityDescriptorDacl(sd.as_ptr().cast_mut().cast(), &mut present, &mut dacl, &mut defaulted)
        };
        // No DACL, or a NULL one: everyone may do anything.
        if read == 0 || present == 0 || dacl.is_null() {
            return false;
        }
        // SAFETY: `dacl` points at the ACL inside `sd`, alive here.
        let count = unsafe { (*dacl).AceCount };
        (0..u32::from(count)).all(|i| {
            let mut ace: *mut core::ffi::c_void = std::ptr::null_mut();
            // SAFETY: `i` is below the ACL's count; `ace` points into the ACL.
            if unsafe { GetAce(dacl, i, &mut ace) } == 0 || ace.is_null() {
                return false;
            }
            // SAFETY: every entry starts with its header.
            let header = unsafe { *ace.cast::<ACE_HEADER>() };
            if u32::from(header.AceFlags) & INHERIT_ONLY_ACE != 0 || NOT_ALLOWING.contains(&header.AceType) {
                return true;
            }
            if header.AceType != ALLOWED {
                return false;
            }
            let allowed = ace.cast::<ACCESS_ALLOWED_ACE>();
            // SAFETY: an ACCESS_ALLOWED_ACE: its mask, then its SID from `SidStart`.
            let (mask, sid): (u32, PSID) = unsafe { ((*allowed).Mask, (&raw mut (*allowed).SidStart).cast()) };
            // SAFETY: `sid` and `owner` point into `sd`, alive here.
            let trusted = || unsafe {
                EqualSid(sid, owner) != 0
                    || token.is_mine(sid)
                    || IsWellKnownSid(sid, WinLocalSystemSid) != 0
                    || IsWellKnownSid(sid, WinBuiltinAdministratorsSid) != 0
            };
            mask & WRITE_RIGHTS == 0 || trusted()
        })
    }

    /// The NUL-terminated wide form of `path`, for the system's calls.
    fn wide(path: &Path) -> Vec<u16> {
        use std::os::windows::ffi::OsStrExt;
        path.as_os_str().encode_wide().chain([0]).collect()
    }

    /// Makes the folder `path` with the owner-only descriptor ([`OwnerOnly`]): a records
    /// folder of this user's alone (`AlreadyExists` where anything is there).
    pub fn create_dir(path: &Path) -> io::Result<()> {
        let private = OwnerOnly::new(true)?;
        let attrs = SECURITY_ATTRIBUTES {
            nLength: size_of::<SECURITY_ATTRIBUTES>() as u32,
            lpSecurityDescriptor: private.descriptor().cast_mut(),
            bInheritHandle: 0,
        };
        let path = wide(path);
        // SAFETY: `path` is NUL-terminated; `attrs` points at the descriptor in `private`,
        // alive through the call.
        if unsafe { CreateDirectoryW(path.as_ptr(), &raw const attrs) } == 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }

    /// Gives the file or folder at `path` the owner-only descriptor ([`OwnerOnly`]): this
    /// user its owner, and the protected DACL of one entry (a record just written whole,
    /// which got what its folder gives a new file).
    pub fn make_owner_only(path: &Path, folder: bool) -> io::Result<()> {
        let private = OwnerOnly::new(folder)?;
        let path = wide(path);
        let info = OWNER_SECURITY_INFORMATION | DACL_SECURITY_INFORMATION | PROTECTED_DACL_SECURITY_INFORMATION;
        // SAFETY: `path` is NUL-terminated; the descriptor in `private` is alive through
        // the call, which only reads it.
        if unsafe { SetFileSecurityW(path.as_ptr(), info, private.descriptor().cast_mut()) } == 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }

    /// The entries of the open folder `parent`'s DACL that what is made in it inherits
    /// (object or container inherit), each made inherit-only and explicit, whole, one after
    /// another; none where the DACL cannot be read.
    fn inheritable_entries(parent: &File) -> Vec<u8> {
        let mut out = Vec::new();
        let Some(sd) = security_of(parent, DACL_SECURITY_INFORMATION) else { return out };
        let (mut present, mut dacl, mut defaulted): (i32, *mut ACL, i32) = (0, std::ptr::null_mut(), 0);
        // SAFETY: `sd` is the security descriptor just read; `dacl` points into it.
        let read = unsafe {
            GetSecurityDescriptorDacl(sd.as_ptr().cast_mut().cast(), &mut present, &mut dacl, &mut defaulted)
        };
        if read == 0 || present == 0 || dacl.is_null() {
            return out;
        }
        // SAFETY: `dacl` points at the ACL inside `sd`, alive here.
        let count = unsafe { (*dacl).AceCount };
        for i in 0..u32::from(count) {
            let mut ace: *mut core::ffi::c_void = std::ptr::null_mut();
            // SAFETY: `i` is below the ACL's count; `ace` points into the ACL.
            if unsafe { GetAce(dacl, i, &mut ace) } == 0 || ace.is_null() {
                continue;
            }
            // SAFETY: every entry starts with its header, and is `AceSize` bytes long.
            let header = unsafe { *ace.cast::<ACE_HEADER>() };
            let flags = u32::from(header.AceFlags);
            if flags & (OBJECT_INHERIT_ACE | CONTAINER_INHERIT_ACE) == 0 {
                continue;
            }
            // SAFETY: as above: the whole entry is inside the ACL.
            let bytes = unsafe { std::slice::from_raw_parts(ace.cast::<u8>(), usize::from(header.AceSize)) };
            let at = out.len();
            out.extend_from_slice(bytes);
            out[at + 1] = ((flags | INHERIT_ONLY_ACE) & !INHERITED_ACE) as u8;
        }
        out
    }

    /// An owner-only security descriptor, to make a file or folder with: owned by this
    /// user, with a protected DACL (nothing inherited from the folder it is made in) of one
    /// entry, this user's SID with full control, inherited by nothing made inside it (a set's
    /// files staged in a working folder get what the system gives a file with no entry to
    /// inherit, as before; only the records and the folders are this user's alone). Under
    /// Wine the Unix mode it is made with follows, whatever the umask: 0770 for a folder,
    /// 0660 for a file (Wine gives the owner's rights to the file's Unix group as well, and
    /// shows no Unix group in a DACL: a classmate in the teacher's own Unix group is not
    /// kept out, nor seen; see docs/security.md).
    pub struct OwnerOnly {
        /// The token's buffers, which the descriptor's owner points into.
        _token: Token,
        /// The ACL, which the descriptor points into.
        _acl: Vec<u64>,
        /// The descriptor itself (absolute: it points at the two above, which live as long
        /// as it does and never move: each is on the heap).
        sd: Box<[u64; 8]>,
    }

    impl OwnerOnly {
        /// This user's owner-only descriptor, for a folder (`folder`: every right) or a
        /// file (every right but executing it: under Wine, no Unix execute bit).
        /// `Err` where the system cannot make one.
        pub fn new(folder: bool) -> io::Result<OwnerOnly> {
            Self::with(if folder { FILE_ALL_ACCESS } else { FILE_ALL_ACCESS & !FILE_EXECUTE }, &[])
        }

        /// This user's owner-only descriptor for a working folder made in the open folder
        /// `parent`: as [`Self::new`], and, for what is made inside it only (inherit-only,
        /// so they give no one any right on the folder itself, and [`super::is_this_users_alone`]
        /// passes over them), the entries `parent` gives what is made in it. A set's files,
        /// staged in the working folder and then moved into `parent`, get what a file made
        /// there gets, as before (on a Windows share, the students' right to read the
        /// sheets), not the token's default (this user, SYSTEM and the Administrators
        /// alone). Under Wine, which keeps no DACL but the Unix mode, nothing changes.
        pub fn folder_in(parent: &File) -> io::Result<OwnerOnly> {
            Self::with(FILE_ALL_ACCESS, &inheritable_entries(parent))
        }

        /// The descriptor: this user the owner; a protected DACL of this user's entry with
        /// `rights`, then the entries `inherited` (whole entries, one after another).
        fn with(rights: u32, inherited: &[u8]) -> io::Result<OwnerOnly> {
            let fail = || io::Error::last_os_error();
            let token = Token::of_process().ok_or_else(fail)?;
            let user = token.user();
            // SAFETY: `user` is the token's SID, alive in `token`.
            let sid_len = unsafe { GetLengthSid(user) } as usize;
            let acl_len =
                (size_of::<ACL>() + size_of::<ACCESS_ALLOWED_ACE>() + sid_len + inherited.len()).next_multiple_of(8);
            let acl_size = u32::try_from(acl_len).ok().filter(|n| *n <= 0xFFFC);
            let Some(acl_size) = acl_size else { return Self::with(rights, &[]) };
            let mut acl = vec![0u64; acl_len / 8];
            let mut sd = Box::new([0u64; 8]);
            let acl_ptr = acl.as_mut_ptr().cast::<ACL>();
            let sd_ptr: *mut core::ffi::c_void = sd.as_mut_ptr().cast();
            // SAFETY: `acl` holds `acl_len` bytes, `sd` 64 (a descriptor needs 40); `user` is
            // the token's SID; `inherited` holds whole entries of its length; each call writes
            // only into those buffers, which outlive it.
            let made = unsafe {
                InitializeAcl(acl_ptr, acl_size, ACL_REVISION_DS) != 0
                    && AddAccessAllowedAceEx(acl_ptr, ACL_REVISION_DS, 0, rights, user) != 0
                    && (inherited.is_empty()
                        || AddAce(
                            acl_ptr,
                            ACL_REVISION_DS,
                            u32::MAX,
                            inherited.as_ptr().cast(),
                            inherited.len() as u32,
                        ) != 0)
                    && InitializeSecurityDescriptor(sd_ptr, SD_REVISION) != 0
                    && SetSecurityDescriptorOwner(sd_ptr, user, 0) != 0
                    && SetSecurityDescriptorDacl(sd_ptr, 1, acl_ptr, 0) != 0
                    && SetSecurityDescriptorControl(sd_ptr, SE_DACL_PROTECTED, SE_DACL_PROTECTED) != 0
            };
            if !made {
                return Err(fail());
            }
            Ok(OwnerOnly { _token: token, _acl: acl, sd })
        }

        /// The descriptor, for `SECURITY_ATTRIBUTES` or `OBJECT_ATTRIBUTES` (valid as long
        /// as `self` is).
        pub fn descriptor(&self) -> *const core::ffi::c_void {
            self.sd.as_ptr().cast()
        }
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        /// The (flags, is this user's SID) of each entry of `owner_only`'s DACL.
        fn entries(owner_only: &OwnerOnly) -> Vec<(u8, bool)> {
            let token = Token::of_process().unwrap();
            let (mut present, mut dacl, mut defaulted): (i32, *mut ACL, i32) = (0, std::ptr::null_mut(), 0);
            // SAFETY: the descriptor is alive in `owner_only`; `dacl` points into its ACL.
            let read = unsafe {
                GetSecurityDescriptorDacl(owner_only.descriptor().cast_mut(), &mut present, &mut dacl, &mut defaulted)
            };
            assert!(read != 0 && present != 0 && !dacl.is_null());
            // SAFETY: as above.
            (0..u32::from(unsafe { (*dacl).AceCount }))
                .map(|i| {
                    let mut ace: *mut core::ffi::c_void = std::ptr::null_mut();
                    // SAFETY: `i` is below the count; the entry is an allowing one here.
                    unsafe {
                        assert!(GetAce(dacl, i, &mut ace) != 0);
                        let allowed = ace.cast::<ACCESS_ALLOWED_ACE>();
                        ((*allowed).Header.AceFlags, token.is_mine((&raw mut (*allowed).SidStart).cast()))
                    }
                })
                .collect()
        }

        /// Issue 59, round 3: a working folder is this user's alone, yet what is staged in
        /// it gets what its parent gives a new file (on a Windows share, the students'
        /// right to read the sheets), as before: the parent's inheritable entries are kept,
        /// inherit-only, after this user's own entry, which nothing inherits.
        #[test]
        fn a_working_folder_is_owner_only_and_passes_on_what_its_parent_gives() {
            use std::os::windows::fs::OpenOptionsExt;
            let plain = OwnerOnly::new(false).unwrap();
            assert_eq!(entries(&plain), [(0, true)], "a record: one entry, this user's, inherited by nothing");
            let dir = std::env::temp_dir().join(format!("phonglab-private {}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            // FILE_FLAG_BACKUP_SEMANTICS: a folder.
            let parent = File::options().read(true).custom_flags(0x0200_0000).open(&dir).unwrap();
            let inheritable = inheritable_entries(&parent);
            let folder = OwnerOnly::folder_in(&parent).unwrap();
            let got = entries(&folder);
            assert_eq!(got[0], (0, true), "this user's own entry first, inherited by nothing");
            assert!(!inheritable.is_empty(), "a temporary folder gives what is made in it some entries");
            assert!(got.len() > 1 && got[1..].iter().all(|(f, _)| u32::from(*f) & INHERIT_ONLY_ACE != 0), "{got:?}");
            assert!(got[1..].iter().all(|(f, _)| u32::from(*f) & INHERITED_ACE == 0), "{got:?}");
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }
}
