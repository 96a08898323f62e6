//! One dispatch for every vector kernel: the processor is asked at run time for the widest
//! instruction set a kernel was written for, and the kernel is compiled for it (pulp's
//! `vectorize`: a function with the target features enabled, into which the kernel's closure is
//! inlined). Every kernel keeps the same arithmetic in the same order in both versions, so the
//! answers do not depend on the processor (Rust never fuses a multiply and an add on its own).

/// `widest!(LEVEL if WIDE, |simd| FAST, SLOW)`: `FAST`, with `simd` bound to pulp's x86-64
/// `LEVEL` token (`V3`: AVX2 and FMA; `V4`: AVX-512) and compiled for it, where the processor has
/// that level and `WIDE` allows it; `SLOW` otherwise (and on other architectures).
/// `widest!(LEVEL, F)`: the closure `F` (marked `#[inline(always)]`), compiled for `LEVEL` where
/// the processor has it, else as it is.
#[cfg(target_arch = "x86_64")]
macro_rules! widest {
    ($level:ident $(if $wide:expr)?, |$simd:ident| $fast:expr, $slow:expr $(,)?) => {
        match if true $(&& $wide)? { pulp::x86::$level::try_new() } else { None } {
            Some($simd) => $simd.vectorize(
                #[inline(always)]
                || $fast,
            ),
            None => $slow,
        }
    };
    ($level:ident, $f:expr $(,)?) => {
        match pulp::x86::$level::try_new() {
            Some(simd) => simd.vectorize($f),
            None => $f(),
        }
    };
}

#[cfg(not(target_arch = "x86_64"))]
macro_rules! widest {
    ($level:ident $(if $wide:expr)?, |$simd:ident| $fast:expr, $slow:expr $(,)?) => {
        $slow
    };
    ($level:ident, $f:expr $(,)?) => {
        $f()
    };
}

pub(crate) use widest;
