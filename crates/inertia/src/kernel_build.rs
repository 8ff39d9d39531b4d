//! Which build of the solid-integration kernel runs: the portable one, or
//! an AVX2/FMA or AVX-512 one on a CPU that has those features. All builds
//! give the same bits (see `solid_kernel`); the choice is about speed, and
//! forcing one (`KREISEL_KERNEL`) is for tests and benchmarks.

use std::fmt;
use std::str::FromStr;

/// The environment variable that forces a build of the kernel.
pub const KERNEL_ENV: &str = "KREISEL_KERNEL";

/// A build of the kernel that sums a mesh's signed tetrahedra
/// ([`crate::MeshMoments::solid`]). Every build performs the same
/// floating-point operations in the same order, so all give the same bits.
///
/// ```
/// use kreisel_inertia::SolidKernel;
/// assert!(SolidKernel::Portable.is_supported());
/// assert_eq!("avx2".parse::<SolidKernel>(), Ok(SolidKernel::Avx2));
/// assert!(SolidKernel::supported().contains(&SolidKernel::fastest()));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SolidKernel {
    /// Plain Rust, one triangle at a time (`f64::mul_add` for the fused
    /// steps); runs on every CPU.
    Portable,
    /// x86-64 with AVX2 and FMA: the coordinates of a triangle in one
    /// 256-bit register.
    Avx2,
    /// x86-64 with AVX-512F/VL and FMA: two triangles per 512-bit register.
    Avx512,
}

/// A request for a kernel build that cannot be honoured.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum KernelError {
    /// The name is none of `portable`, `avx2`, `avx512`.
    #[error("unknown kernel build {name:?}: expected portable, avx2 or avx512")]
    UnknownName {
        /// The name as given.
        name: String,
    },
    /// This CPU lacks features the build needs (running it would execute
    /// illegal instructions).
    #[error("the {kernel} kernel build needs CPU features {needs}, which this CPU lacks")]
    Unsupported {
        /// The build asked for.
        kernel: SolidKernel,
        /// The features it needs.
        needs: &'static str,
    },
}

impl SolidKernel {
    /// Every build, portable first.
    pub const ALL: [SolidKernel; 3] = [Self::Portable, Self::Avx2, Self::Avx512];

    /// The build's name as `KREISEL_KERNEL` spells it.
    ///
    /// ```
    /// assert_eq!(kreisel_inertia::SolidKernel::Avx512.name(), "avx512");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Self::Portable => "portable",
            Self::Avx2 => "avx2",
            Self::Avx512 => "avx512",
        }
    }

    /// The CPU features the build needs.
    fn needs(self) -> &'static str {
        match self {
            Self::Portable => "none",
            Self::Avx2 => "avx2 and fma",
            Self::Avx512 => "avx512f, avx512vl and fma",
        }
    }

    /// Whether this CPU runs the build (checked at run time).
    ///
    /// ```
    /// assert!(kreisel_inertia::SolidKernel::Portable.is_supported());
    /// ```
    pub fn is_supported(self) -> bool {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::is_x86_feature_detected as has;
            match self {
                Self::Portable => true,
                Self::Avx2 => has!("avx2") && has!("fma"),
                Self::Avx512 => has!("avx512f") && has!("avx512vl") && has!("fma"),
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            self == Self::Portable
        }
    }

    /// `Ok(self)` if this CPU runs the build.
    ///
    /// # Errors
    /// [`KernelError::Unsupported`] if the CPU lacks a feature it needs.
    ///
    /// ```
    /// use kreisel_inertia::SolidKernel;
    /// assert_eq!(SolidKernel::Portable.check(), Ok(SolidKernel::Portable));
    /// ```
    pub fn check(self) -> Result<Self, KernelError> {
        if self.is_supported() {
            Ok(self)
        } else {
            Err(KernelError::Unsupported {
                kernel: self,
                needs: self.needs(),
            })
        }
    }

    /// The builds this CPU runs, portable first.
    ///
    /// ```
    /// use kreisel_inertia::SolidKernel;
    /// assert_eq!(SolidKernel::supported()[0], SolidKernel::Portable);
    /// ```
    pub fn supported() -> Vec<SolidKernel> {
        Self::ALL.into_iter().filter(|k| k.is_supported()).collect()
    }

    /// The fastest build this CPU runs.
    ///
    /// ```
    /// assert!(kreisel_inertia::SolidKernel::fastest().is_supported());
    /// ```
    pub fn fastest() -> SolidKernel {
        Self::supported()
            .last()
            .copied()
            .unwrap_or(SolidKernel::Portable)
    }

    /// The build `KREISEL_KERNEL` asks for: `Ok(None)` when it is unset or
    /// empty.
    ///
    /// # Errors
    /// [`KernelError::UnknownName`] for a name other than `portable`,
    /// `avx2`, `avx512` (any case, surrounding spaces ignored), and
    /// [`KernelError::Unsupported`] for a build this CPU cannot run.
    ///
    /// ```
    /// use kreisel_inertia::SolidKernel;
    /// if std::env::var_os("KREISEL_KERNEL").is_none() {
    ///     assert_eq!(SolidKernel::from_env(), Ok(None));
    /// }
    /// ```
    pub fn from_env() -> Result<Option<SolidKernel>, KernelError> {
        let value = std::env::var(KERNEL_ENV).unwrap_or_default();
        requested(&value, SolidKernel::is_supported)
    }

    /// The build [`crate::MeshMoments::solid`] uses, decided once per
    /// process: the one `KREISEL_KERNEL` names if this CPU runs it, else
    /// the fastest this CPU runs (an unknown name or a build the CPU lacks
    /// never runs illegal instructions; [`SolidKernel::from_env`] says why
    /// the request was not honoured).
    ///
    /// ```
    /// assert!(kreisel_inertia::SolidKernel::active().is_supported());
    /// ```
    pub fn active() -> SolidKernel {
        static ACTIVE: std::sync::OnceLock<SolidKernel> = std::sync::OnceLock::new();
        *ACTIVE.get_or_init(|| {
            SolidKernel::from_env()
                .ok()
                .flatten()
                .unwrap_or_else(SolidKernel::fastest)
        })
    }
}

/// The build `value` (a `KREISEL_KERNEL` setting) asks for on a CPU that
/// runs the builds for which `supported` is true.
fn requested(
    value: &str,
    supported: impl Fn(SolidKernel) -> bool,
) -> Result<Option<SolidKernel>, KernelError> {
    if value.trim().is_empty() {
        return Ok(None);
    }
    let kernel: SolidKernel = value.parse()?;
    if supported(kernel) {
        Ok(Some(kernel))
    } else {
        Err(KernelError::Unsupported {
            kernel,
            needs: kernel.needs(),
        })
    }
}

impl FromStr for SolidKernel {
    type Err = KernelError;

    fn from_str(s: &str) -> Result<Self, KernelError> {
        let name = s.trim().to_ascii_lowercase();
        Self::ALL
            .into_iter()
            .find(|k| k.name() == name)
            .ok_or(KernelError::UnknownName { name: s.to_owned() })
    }
}

impl fmt::Display for SolidKernel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A CPU without AVX-512: asking for it is refused (never run), asking
    /// for AVX2 or the portable build is honoured.
    #[test]
    fn a_build_the_cpu_lacks_is_refused() {
        let no_avx512 = |k: SolidKernel| k != SolidKernel::Avx512;
        assert_eq!(
            requested("avx512", no_avx512),
            Err(KernelError::Unsupported {
                kernel: SolidKernel::Avx512,
                needs: "avx512f, avx512vl and fma"
            })
        );
        assert_eq!(requested(" AVX2 ", no_avx512), Ok(Some(SolidKernel::Avx2)));
        let portable_only = |k: SolidKernel| k == SolidKernel::Portable;
        assert!(matches!(
            requested("avx2", portable_only),
            Err(KernelError::Unsupported { .. })
        ));
        assert_eq!(
            requested("portable", portable_only),
            Ok(Some(SolidKernel::Portable))
        );
    }

    /// Unset or empty asks for nothing; a misspelt name is an error naming it.
    #[test]
    fn names_are_checked() {
        assert_eq!(requested("", |_| true), Ok(None));
        assert_eq!(requested("  ", |_| true), Ok(None));
        let err = requested("avx-512", |_| true).unwrap_err();
        assert_eq!(
            err.to_string(),
            "unknown kernel build \"avx-512\": expected portable, avx2 or avx512"
        );
        for k in SolidKernel::ALL {
            assert_eq!(requested(k.name(), |_| true), Ok(Some(k)));
        }
    }
}
