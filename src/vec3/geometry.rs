//! [`Vec3`]'s geometry beyond the dot and cross products: projections, distances,
//! reflection, interpolation, clamps and angles, each rounded through the scalar.

use super::Vec3;
use crate::Scalar;

/// How far from one [`Vec3::is_normalized`] lets a squared length be.
pub(crate) const SQUARED_LENGTH_TOLERANCE: f64 = 2e-4;

impl<S: Scalar> Vec3<S> {
    /// The part of this vector along the unit vector `n`: `n (self · n)`, the dot product
    /// rounded once and each product as [`scale`](Self::scale) rounds it.
    pub fn project_onto_normalized(self, n: Self) -> Self {
        n.scale(S::dot(self, n))
    }

    /// The part of this vector across the unit vector `n`: `self - n (self · n)`. With `n` a
    /// floor's normal (e.g. [`Slide::floor_normal`](crate::Slide::floor_normal)), a character's
    /// wished velocity along the floor.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let wish = Vec3::new(2.0f32, 0.0, 1.0);
    /// let up = Vec3::Y;
    /// assert_eq!(wish.reject_from_normalized(up), wish);
    /// let floor = Vec3::new(0.6f32, 0.8, 0.0); // a slope rising along -x
    /// let along = wish.reject_from_normalized(floor);
    /// assert!(along.dot(floor).abs() < 1e-6);
    /// ```
    pub fn reject_from_normalized(self, n: Self) -> Self {
        self - self.project_onto_normalized(n)
    }

    /// This vector reflected in the plane of the unit normal `n`: `self - 2 n (self · n)`, as
    /// [`project_onto_normalized`](Self::project_onto_normalized) rounds its part along `n`
    /// (glam's `reflect`). A ball's velocity bouncing off a contact:
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let velocity = Vec3::new(3.0f32, -4.0, 0.0);
    /// assert_eq!(velocity.reflect(Vec3::Y), Vec3::new(3.0, 4.0, 0.0));
    /// ```
    pub fn reflect(self, n: Self) -> Self {
        let along = self.project_onto_normalized(n);
        self - along - along
    }

    /// The distance to `o`: [`length`](Self::length) of the difference (which, for points
    /// within the safe range, does not overflow).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// assert_eq!(Vec3::new(1.0f32, 2.0, 3.0).distance(Vec3::new(4.0, 6.0, 3.0)), 5.0);
    /// ```
    pub fn distance(self, o: Self) -> S {
        (o - self).length()
    }

    /// The point a fraction `t` of the way to `o`: `self + (o - self) * t`, the product rounded
    /// as [`scale`](Self::scale) rounds, and `o` itself at `t = 1` (where the sum could miss it
    /// by a rounding): `t = 0` gives `self`, `t = 1` gives `o` and `a.lerp(a, t)` gives `a`,
    /// exactly.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let (a, b) = (Vec3::new(0.0f64, 2.0, -4.0), Vec3::new(1.0, 0.0, 4.0));
    /// assert_eq!(a.lerp(b, 0.25), Vec3::new(0.25, 1.5, -2.0));
    /// assert_eq!(a.lerp(b, 1.0), b);
    /// ```
    pub fn lerp(self, o: Self, t: S) -> Self {
        if t == S::ONE {
            o
        } else {
            self + (o - self).scale(t)
        }
    }

    /// The squared distance to `o` ([`length_squared`](Self::length_squared) of the difference:
    /// fixed point saturates beyond the type's range, [`distance`](Self::distance) does not).
    pub fn distance_squared(self, o: Self) -> S {
        (o - self).length_squared()
    }

    /// `1 / length`, rounded once (the zero vector: infinity for floats; fixed point saturates).
    pub fn length_recip(self) -> S {
        S::ONE.div(self.length())
    }

    /// The unit vector in this direction, or `fallback` where
    /// [`try_normalize`](Self::try_normalize) gives `None`.
    pub fn normalize_or(self, fallback: Self) -> Self {
        self.try_normalize().unwrap_or(fallback)
    }

    /// Whether the length is one within `1e-4` (glam's test: the squared length within `2e-4`
    /// of one).
    pub fn is_normalized(self) -> bool {
        (self.length_squared() - S::ONE).abs() <= S::from_f64(SQUARED_LENGTH_TOLERANCE)
    }

    /// The part of this vector along `o` (any length): along `o`'s unit vector, or zero where
    /// `o` has no direction (zero or not finite). The unit vector is kept in the scalar's
    /// unit-vector precision (30 fractional bits in `I16F16`), so the result is a few steps off
    /// whatever the lengths; with `o` already a unit vector in `S`,
    /// [`project_onto_normalized`](Self::project_onto_normalized) saves the normalisation.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let v = Vec3::new(3.0f32, 4.0, 0.0);
    /// assert_eq!(v.project_onto(Vec3::new(0.0, 10.0, 0.0)), Vec3::new(0.0, 4.0, 0.0));
    /// assert_eq!(v.reject_from(Vec3::new(0.0, 10.0, 0.0)), Vec3::new(3.0, 0.0, 0.0));
    /// assert_eq!(v.project_onto(Vec3::ZERO), Vec3::ZERO);
    /// ```
    pub fn project_onto(self, o: Self) -> Self {
        let Some((_, n)) = o.is_finite().then(|| S::direction(o)).flatten() else {
            return Self::ZERO;
        };
        let along = S::dot_unit(self, n);
        n.map(|u| S::mul_unit(along, u))
    }

    /// The part of this vector across `o` (any length): `self` less
    /// [`project_onto`](Self::project_onto), all of `self` where `o` has no direction.
    pub fn reject_from(self, o: Self) -> Self {
        self - self.project_onto(o)
    }

    /// Each component held within `[min, max]` of the same component (`min <= max` assumed: where
    /// not, `max` wins).
    pub fn clamp(self, min: Self, max: Self) -> Self {
        self.max(min).min(max)
    }

    /// This vector, shortened to length `max` where longer (a speed cap); the direction kept
    /// to the scalar's rounding. A `max` of zero or below (or NaN) gives zero.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let v = Vec3::new(6.0f64, 8.0, 0.0);
    /// assert_eq!(v.clamp_length_max(5.0), Vec3::new(3.0, 4.0, 0.0));
    /// assert_eq!(v.clamp_length_max(20.0), v);
    /// ```
    pub fn clamp_length_max(self, max: S) -> Self {
        // Zero or below, or NaN.
        if max.partial_cmp(&S::ZERO) != Some(core::cmp::Ordering::Greater) {
            return Self::ZERO;
        }
        let length = self.length();
        if length > max {
            // Each component times `max / length` rounded once (fixed point: exactly, then
            // rounded): the ratio alone, rounded, would be off by a step times the length.
            self.map(|c| S::mul_div(c, max, length))
        } else {
            self
        }
    }

    /// The point at most `distance` from this one towards `target`: `target` itself where it is
    /// that close (a camera or a platform closing in at a limited speed); this one for a
    /// `distance` of zero or below.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let (a, b) = (Vec3::new(0.0f32, 0.0, 0.0), Vec3::new(0.0, 0.0, 10.0));
    /// assert_eq!(a.move_towards(b, 4.0), Vec3::new(0.0, 0.0, 4.0));
    /// assert_eq!(a.move_towards(b, 40.0), b);
    /// ```
    pub fn move_towards(self, target: Self, distance: S) -> Self {
        if distance.partial_cmp(&S::ZERO) != Some(core::cmp::Ordering::Greater) {
            return self;
        }
        let gap = target - self;
        let length = gap.length();
        if length <= distance {
            target
        } else {
            self + gap.map(|c| S::mul_div(c, distance, length))
        }
    }

    /// The angle between this vector and `o`, in radians in `[0, π]`, from the dot product of
    /// their unit vectors (`libm`'s `acos` in `f64`, then rounded to `S`: the same on every
    /// target); `None` where either has no direction (zero or not finite).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let right = Vec3::X.angle_between(Vec3::<f64>::Y).unwrap();
    /// assert!((right - core::f64::consts::FRAC_PI_2).abs() < 1e-12);
    /// assert_eq!(Vec3::<f64>::ZERO.angle_between(Vec3::X), None);
    /// ```
    pub fn angle_between(self, o: Self) -> Option<S> {
        let (a, b) = (self.try_normalize()?, o.try_normalize()?);
        let cos = a.dot(b).to_f64().clamp(-1.0, 1.0);
        Some(S::from_f64(libm::acos(cos)))
    }
}
