//! The little linear algebra the geometry stage needs: 3-vectors as `[f64; 3]`,
//! 3x3 and 4x4 matrices acting on column vectors (`m[row][col]`).

pub type Vec3 = [f64; 3];
pub type Vec4 = [f64; 4];

pub fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: Vec3, s: f64) -> Vec3 {
    a.map(|v| v * s)
}

pub fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn length(a: Vec3) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or `None` for a zero (or non-finite) vector.
pub fn normalize(a: Vec3) -> Option<Vec3> {
    let len = length(a);
    (len > 0.0 && len.is_finite()).then(|| scale(a, 1.0 / len))
}

/// Twice the area vector of triangle (a, b, c): (b - a) x (c - a). It points to
/// the side from which a -> b -> c runs counter-clockwise.
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    cross(sub(b, a), sub(c, a))
}

/// A linear map of 3-space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat3(pub [[f64; 3]; 3]);

impl Mat3 {
    pub const IDENTITY: Mat3 = Mat3([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);

    pub fn diagonal(d: Vec3) -> Mat3 {
        Mat3([[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]])
    }

    /// Rotation by `deg` degrees about coordinate axis `axis` (0 = x, 1 = y,
    /// 2 = z), counter-clockwise looking from the positive axis toward the origin.
    pub fn rotation(axis: usize, deg: f64) -> Mat3 {
        let (s, c) = deg.to_radians().sin_cos();
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let mut m = Mat3::IDENTITY;
        m.0[i][i] = c;
        m.0[i][j] = -s;
        m.0[j][i] = s;
        m.0[j][j] = c;
        m
    }

    pub fn mul(&self, o: &Mat3) -> Mat3 {
        Mat3(std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| self.0[r][k] * o.0[k][c]).sum())))
    }

    pub fn apply(&self, v: Vec3) -> Vec3 {
        self.0.map(|row| dot(row, v))
    }

    pub fn determinant(&self) -> f64 {
        let m = &self.0;
        dot(m[0], cross(m[1], m[2]))
    }

    /// The inverse transpose, which carries normals when `self` carries
    /// positions; `None` when `self` is singular.
    pub fn inverse_transpose(&self) -> Option<Mat3> {
        let det = self.determinant();
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // M^-1 has the columns r1 x r2, r2 x r0, r0 x r1 (over det) for the rows
        // r0, r1, r2 of M, since r_i . (r_j+1 x r_j+2) = det when i = j, else 0.
        // Those are the rows of M^-T.
        let m = &self.0;
        let rows = [cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1])];
        Some(Mat3(rows.map(|r| scale(r, 1.0 / det))))
    }
}

/// A projective map of 3-space in homogeneous coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat4(pub [[f64; 4]; 4]);

impl Mat4 {
    /// `[linear | translate]` over `[0 0 0 1]`.
    pub fn affine(linear: &Mat3, translate: Vec3) -> Mat4 {
        let l = &linear.0;
        Mat4([
            [l[0][0], l[0][1], l[0][2], translate[0]],
            [l[1][0], l[1][1], l[1][2], translate[1]],
            [l[2][0], l[2][1], l[2][2], translate[2]],
            [0.0, 0.0, 0.0, 1.0],
        ])
    }

    pub fn mul(&self, o: &Mat4) -> Mat4 {
        Mat4(std::array::from_fn(|r| std::array::from_fn(|c| (0..4).map(|k| self.0[r][k] * o.0[k][c]).sum())))
    }

    /// The image of point `p` (w = 1), in homogeneous coordinates.
    pub fn apply_point(&self, p: Vec3) -> Vec4 {
        self.0.map(|row| row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn math_inverse_transpose_undoes_the_transpose_product() {
        let m = Mat3::rotation(0, 30.0).mul(&Mat3::diagonal([2.0, -3.0, 0.5])).mul(&Mat3::rotation(1, 70.0));
        let it = m.inverse_transpose().unwrap();
        // (M^-T)^T M = M^-1 M = I.
        let t = Mat3(std::array::from_fn(|r| std::array::from_fn(|c| it.0[c][r])));
        let p = t.mul(&m);
        for r in 0..3 {
            for c in 0..3 {
                let want = if r == c { 1.0 } else { 0.0 };
                assert!((p.0[r][c] - want).abs() < 1e-12, "({r},{c}) = {}", p.0[r][c]);
            }
        }
        assert_eq!(Mat3::diagonal([1.0, 0.0, 1.0]).inverse_transpose(), None);
    }

    #[test]
    fn math_rotation_is_counter_clockwise_about_each_axis() {
        // x -> y about z, y -> z about x, z -> x about y.
        let near = |a: Vec3, b: Vec3| (0..3).all(|k| (a[k] - b[k]).abs() < 1e-15);
        assert!(near(Mat3::rotation(2, 90.0).apply([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]));
        assert!(near(Mat3::rotation(0, 90.0).apply([0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]));
        assert!(near(Mat3::rotation(1, 90.0).apply([0.0, 0.0, 1.0]), [1.0, 0.0, 0.0]));
    }
}
