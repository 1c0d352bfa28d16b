//! The few structs of XLA's FFI C API (`xla/ffi/api/c_api.h`, API
//! version 0.3, as shipped in jaxlib's `jax.ffi.include_dir()`) that the
//! handlers read, written by hand: only the fields used, in the header's
//! order. Also the common body of a handler ([`handle`]: the frame's size,
//! XLA's metadata query, the stages, panics caught), errors through the
//! API's own `XLA_FFI_Error_Create`, and the decoding of buffers and scalar
//! attributes with their checks (dtype, rank, shape, alignment), each
//! error naming the argument.

use std::borrow::Cow;
use std::ffi::{c_char, c_int, c_void, CString};
use std::mem::{offset_of, size_of};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::ptr::null_mut;

// The C API's constants (c_api.h; C enums are `int`).
const API_MAJOR: c_int = 0;
const API_MINOR: c_int = 3;
const EXTENSION_METADATA: c_int = 1;
const STAGE_EXECUTE: c_int = 3;
const BUFFER: c_int = 1; // XLA_FFI_ArgType_BUFFER and XLA_FFI_RetType_BUFFER
const ATTR_SCALAR: c_int = 3;
pub(super) const S8: c_int = 2;
pub(super) const S64: c_int = 5;
pub(super) const F32: c_int = 11;
pub(super) const F64: c_int = 12;
pub(super) const INVALID_ARGUMENT: c_int = 3;
pub(super) const INTERNAL: c_int = 13;

#[repr(C)]
struct ExtensionBase {
    struct_size: usize,
    kind: c_int,
    next: *mut ExtensionBase,
}

#[repr(C)]
struct ApiVersion {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    major: c_int,
    minor: c_int,
}

/// An XLA error (opaque; created by the API, owned by XLA once returned).
#[repr(C)]
pub(super) struct XlaError {
    _opaque: [u8; 0],
}

#[repr(C)]
struct ErrorCreateArgs {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    message: *const c_char,
    errc: c_int,
}

/// The head of `XLA_FFI_Api`: the handlers only create errors.
#[repr(C)]
struct Api {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    api_version: ApiVersion,
    internal_api: *const c_void,
    error_create: Option<unsafe extern "C" fn(*mut ErrorCreateArgs) -> *mut XlaError>,
}

#[repr(C)]
struct Buffer {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    dtype: c_int,
    data: *mut c_void,
    rank: i64,
    dims: *const i64,
}

/// `XLA_FFI_Args` and `XLA_FFI_Rets` (the same layout).
#[repr(C)]
pub(super) struct List {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    size: i64,
    types: *const c_int,
    items: *const *mut c_void,
}

#[repr(C)]
struct ByteSpan {
    ptr: *const c_char,
    len: usize,
}

#[repr(C)]
struct Scalar {
    dtype: c_int,
    value: *const c_void,
}

#[repr(C)]
struct Attrs {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    size: i64,
    types: *const c_int,
    names: *const *const ByteSpan,
    attrs: *const *const c_void,
}

/// `XLA_FFI_CallFrame`, what XLA passes to a handler.
#[repr(C)]
pub(super) struct CallFrame {
    struct_size: usize,
    extension_start: *mut ExtensionBase,
    api: *const Api,
    ctx: *mut c_void,
    stage: c_int,
    pub(super) args: List,
    pub(super) rets: List,
    attrs: Attrs,
    future: *mut c_void,
}

#[repr(C)]
struct Metadata {
    struct_size: usize,
    api_version: ApiVersion,
    traits: u32,
    state_type_id: i64,
}

#[repr(C)]
struct MetadataExtension {
    base: ExtensionBase,
    metadata: *mut Metadata,
}

// The header's STRUCT_SIZEs: up to the end of the last field it names.
const CALL_FRAME_SIZE: usize = offset_of!(CallFrame, attrs) + size_of::<Attrs>();
const ERROR_ARGS_SIZE: usize = offset_of!(ErrorCreateArgs, errc) + size_of::<c_int>();
const API_VERSION_SIZE: usize = offset_of!(ApiVersion, minor) + size_of::<c_int>();
const METADATA_SIZE: usize = offset_of!(Metadata, traits) + size_of::<u32>();

/// A handler's failure: an XLA error code and the message.
pub(super) type Fail = (c_int, String);

pub(super) fn invalid(message: String) -> Fail {
    (INVALID_ARGUMENT, message)
}

/// The library's error as the code a NumPy user's exception would map to
/// (`ValueError` for bad values, `RuntimeError` for the rest: [`crate::to_py_err`]).
pub(super) fn library(e: lcpbatch::Error) -> Fail {
    let code = match e {
        lcpbatch::Error::Invalid { .. } | lcpbatch::Error::Unsupported(_) => INVALID_ARGUMENT,
        _ => INTERNAL,
    };
    (code, e.to_string())
}

/// An XLA error made by the API's own `XLA_FFI_Error_Create` (null, which
/// XLA reads as success, only if the API has no such function).
///
/// # Safety
/// `api` is the call frame's API pointer (valid for the call).
unsafe fn error(api: *const Api, (code, message): Fail) -> *mut XlaError {
    let Some(create) = (unsafe { api.as_ref() }).and_then(|a| a.error_create) else {
        return null_mut();
    };
    let message = CString::new(message.replace('\0', " ")).unwrap_or_default();
    let mut args = ErrorCreateArgs {
        struct_size: ERROR_ARGS_SIZE,
        extension_start: null_mut(),
        message: message.as_ptr(),
        errc: code,
    };
    // SAFETY: the API's function, with arguments laid out as c_api.h says;
    // XLA copies the message before `message` is dropped.
    unsafe { create(&mut args) }
}

/// Answers XLA's metadata query: the API version these structs follow, no
/// traits, no state.
///
/// # Safety
/// `ext` is the call frame's metadata extension.
unsafe fn metadata(api: *const Api, ext: *mut MetadataExtension) -> *mut XlaError {
    // SAFETY: XLA passes a live extension; sizes are checked before use.
    let ext = unsafe { &mut *ext };
    if ext.base.struct_size < size_of::<MetadataExtension>() || ext.metadata.is_null() {
        return unsafe { error(api, invalid("XLA_FFI_Metadata_Extension: too small".into())) };
    }
    let m = unsafe { &mut *ext.metadata };
    if m.struct_size < METADATA_SIZE {
        return unsafe { error(api, invalid("XLA_FFI_Metadata: too small".into())) };
    }
    m.api_version = ApiVersion {
        struct_size: API_VERSION_SIZE,
        extension_start: null_mut(),
        major: API_MAJOR,
        minor: API_MINOR,
    };
    m.traits = 0;
    if m.struct_size >= offset_of!(Metadata, state_type_id) + size_of::<i64>() {
        m.state_type_id = 0; // XLA_FFI_UNKNOWN_TYPE_ID: stateless
    }
    null_mut()
}

/// The body of every handler: checks the frame, answers the metadata
/// query, skips the stages before `execute`, and runs `body` with panics
/// caught (a panic becomes an `INTERNAL` error, never an unwind into XLA).
///
/// # Safety
/// `frame` is the call frame XLA passes to the handler.
pub(super) unsafe fn handle(
    frame: *mut CallFrame,
    body: fn(&CallFrame) -> Result<(), Fail>,
) -> *mut XlaError {
    // SAFETY: XLA passes a live call frame for the duration of the call.
    let Some(frame) = (unsafe { frame.as_ref() }) else {
        return null_mut();
    };
    let api = frame.api;
    if frame.struct_size < CALL_FRAME_SIZE {
        let message = format!(
            "XLA_FFI_CallFrame: size {} where lcpbatch expects at least {CALL_FRAME_SIZE}; \
             this jaxlib's FFI is older than lcpbatch's",
            frame.struct_size
        );
        return unsafe { error(api, invalid(message)) };
    }
    let ext = frame.extension_start;
    if !ext.is_null() && unsafe { (*ext).kind } == EXTENSION_METADATA {
        return unsafe { metadata(api, ext.cast()) };
    }
    if frame.stage != STAGE_EXECUTE {
        return null_mut();
    }
    match catch_unwind(AssertUnwindSafe(|| body(frame))) {
        Ok(Ok(())) => null_mut(),
        Ok(Err(fail)) => unsafe { error(api, fail) },
        Err(payload) => {
            let message = format!(
                "lcpbatch internal error (a bug, please report it): {}",
                crate::panic_message(&payload)
            );
            unsafe { error(api, (INTERNAL, message)) }
        }
    }
}
pub(super) fn dtype_name(code: c_int) -> String {
    let name = match code {
        1 => "bool",
        2 => "int8",
        3 => "int16",
        4 => "int32",
        5 => "int64",
        6 => "uint8",
        7 => "uint16",
        8 => "uint32",
        9 => "uint64",
        10 => "float16",
        11 => "float32",
        12 => "float64",
        15 => "complex64",
        16 => "bfloat16",
        18 => "complex128",
        _ => return format!("XLA type {code}"),
    };
    name.to_string()
}

/// A shape as Python writes a tuple: "(3, 2)", "(3,)", "()".
pub(super) fn shape(dims: &[i64]) -> String {
    let inner: Vec<String> = dims.iter().map(i64::to_string).collect();
    match inner.len() {
        1 => format!("({},)", inner[0]),
        _ => format!("({})", inner.join(", ")),
    }
}

/// One argument or result buffer, named for errors.
pub(super) struct Buf<'a> {
    pub(super) name: &'static str,
    pub(super) dtype: c_int,
    pub(super) data: *mut c_void,
    pub(super) dims: &'a [i64],
}

impl Buf<'_> {
    /// Its number of entries (every dimension ≥ 0, no overflow).
    pub(super) fn len(&self) -> Result<usize, Fail> {
        self.dims
            .iter()
            .try_fold(1usize, |acc, &d| {
                usize::try_from(d).ok().and_then(|d| acc.checked_mul(d))
            })
            .ok_or_else(|| invalid(format!("{}: bad shape {}", self.name, shape(self.dims))))
    }

    /// Its data as `len` entries of `T` (`T` must be its dtype: checked by
    /// the callers before; the pointer's alignment is checked here).
    fn parts<T>(&self) -> Result<(*mut T, usize), Fail> {
        let len = self.len()?;
        if len == 0 {
            return Ok((std::ptr::NonNull::dangling().as_ptr(), 0));
        }
        if self.data.is_null() || !self.data.cast::<T>().is_aligned() {
            return Err(invalid(format!("{}: unaligned or null data", self.name)));
        }
        Ok((self.data.cast::<T>(), len))
    }

    /// An argument's entries, read only.
    ///
    /// # Safety
    /// `T` is the buffer's dtype; the buffer is XLA's, live for the call.
    pub(super) unsafe fn view<T>(&self) -> Result<&[T], Fail> {
        let (p, len) = self.parts::<T>()?;
        // SAFETY: `len` aligned entries of `T` (the caller's promise).
        Ok(unsafe { std::slice::from_raw_parts(p, len) })
    }

    /// A result's entries, to write.
    ///
    /// # Safety
    /// As [`Buf::view`]; and no other slice of this buffer is alive (each
    /// result is its own buffer: the handlers declare no aliasing).
    #[allow(clippy::mut_from_ref)]
    pub(super) unsafe fn view_mut<T>(&self) -> Result<&mut [T], Fail> {
        let (p, len) = self.parts::<T>()?;
        // SAFETY: as `view`, and exclusive (the caller's promise).
        Ok(unsafe { std::slice::from_raw_parts_mut(p, len) })
    }

    /// Its entries as f64: in place for float64, widened (exactly) for float32.
    pub(super) fn reals(&self) -> Result<Cow<'_, [f64]>, Fail> {
        // SAFETY: the dtype is checked by `expect`/`problem` before.
        Ok(match self.dtype {
            F64 => Cow::Borrowed(unsafe { self.view::<f64>() }?),
            _ => Cow::Owned(
                unsafe { self.view::<f32>() }?
                    .iter()
                    .map(|&v| f64::from(v))
                    .collect(),
            ),
        })
    }

    /// Checks its dtype and shape against `dtype` and `dims`.
    pub(super) fn expect(&self, dtype: c_int, dims: &[i64], like: &str) -> Result<(), Fail> {
        if self.dtype != dtype || self.dims != dims {
            return Err(invalid(format!(
                "{}: expected {} of shape {} (as {like}), got {} of shape {}",
                self.name,
                dtype_name(dtype),
                shape(dims),
                dtype_name(self.dtype),
                shape(self.dims)
            )));
        }
        Ok(())
    }

    /// Writes `values` (f64) into the buffer, rounding for float32.
    pub(super) fn put(&self, values: &[f64]) -> Result<(), Fail> {
        // SAFETY: the dtype is checked by `expect` before.
        match self.dtype {
            F64 => unsafe { self.view_mut::<f64>() }?.copy_from_slice(values),
            _ => {
                let out = unsafe { self.view_mut::<f32>() }?;
                for (o, &v) in out.iter_mut().zip(values) {
                    *o = v as f32;
                }
            }
        }
        Ok(())
    }
}

/// The buffers of `list` (the frame's args or rets, `what`), one per name.
pub(super) fn buffers<'a, const K: usize>(
    list: &'a List,
    names: [&'static str; K],
    what: &str,
) -> Result<[Buf<'a>; K], Fail> {
    if list.size != K as i64 {
        return Err(invalid(format!(
            "{what}: expected {K} ({}), got {}",
            names.join(", "),
            list.size
        )));
    }
    let mut out = Vec::with_capacity(K);
    for (k, name) in names.into_iter().enumerate() {
        // SAFETY: XLA's arrays of `size` types and pointers.
        let (kind, item) = unsafe { (*list.types.add(k), *list.items.add(k)) };
        if kind != BUFFER || item.is_null() {
            return Err(invalid(format!("{name}: not a buffer")));
        }
        // SAFETY: a buffer type's item points at an XLA_FFI_Buffer.
        let b = unsafe { &*item.cast::<Buffer>() };
        let rank = usize::try_from(b.rank).unwrap_or(0);
        let dims = if rank == 0 || b.dims.is_null() {
            &[][..]
        } else {
            // SAFETY: `rank` dimensions.
            unsafe { std::slice::from_raw_parts(b.dims, rank) }
        };
        out.push(Buf {
            name,
            dtype: b.dtype,
            data: b.data,
            dims,
        });
    }
    out.try_into()
        .map_err(|_| invalid(format!("{what}: internal count")))
}

/// The scalar attribute `name` of dtype `dtype`, its value's pointer.
pub(super) fn scalar(frame: &CallFrame, name: &str, dtype: c_int) -> Result<*const c_void, Fail> {
    let a = &frame.attrs;
    for k in 0..usize::try_from(a.size).unwrap_or(0) {
        // SAFETY: XLA's arrays of `size` types, names and attributes.
        let (kind, span, attr) = unsafe { (*a.types.add(k), &**a.names.add(k), *a.attrs.add(k)) };
        // SAFETY: a byte span of `len` bytes.
        let key = unsafe { std::slice::from_raw_parts(span.ptr.cast::<u8>(), span.len) };
        if key != name.as_bytes() {
            continue;
        }
        // SAFETY: a scalar attribute points at an XLA_FFI_Scalar.
        let s = (kind == ATTR_SCALAR).then(|| unsafe { &*attr.cast::<Scalar>() });
        return match s {
            Some(s) if s.dtype == dtype && !s.value.is_null() => Ok(s.value),
            _ => Err(invalid(format!(
                "{name}: expected a {} scalar attribute",
                dtype_name(dtype)
            ))),
        };
    }
    Err(invalid(format!("{name}: missing attribute")))
}
