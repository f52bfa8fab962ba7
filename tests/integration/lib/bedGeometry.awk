#------------------------------------------------------------------------------
# Geometry of a packed bed from rbdPackBed's outputs, independently of the
# code that wrote them: reads postProcessing/rbdPackBed/pellets.csv (first
# file) and constant/triSurface/pellets.stl (ASCII, second file; the pellets'
# facets one pellet after another, in the order of pellets.csv) and prints
# name value lines:
#   pellets        rows of pellets.csv
#   facets         facets of pellets.stl
#   maxRho         largest distance of a vertex from the tube axis [m]
#   minZ, maxZ     lowest and highest vertex [m]
#   maxPoseError   largest distance between a vertex taken back to the body
#                  frame by its pellet's pose (pellets.csv) and the same
#                  vertex of pellet 0 [m]: 0 when every part of pellets.stl
#                  is the same body mesh placed at the pose of pellets.csv
#   volume         volume of pellet 0's closed mesh (divergence theorem) [m^3]
#   bodyMaxR       largest distance of a body-frame vertex from the body
#                  origin [m]
#   bodyMaxAbsZ    largest |z| of a body-frame vertex [m]
#   bodyMaxRhoZ    largest distance of a body-frame vertex from the body z
#                  axis [m]
#   (with -v radii=FILE) pellet 0's body-frame vertex distances from the
#   origin, one per facet corner, sorted, to FILE
#
# Usage: awk -F, -f bedGeometry.awk pellets.csv pellets.stl
#------------------------------------------------------------------------------
function tobody(i, X, Y, Z,    dx, dy, dz, w, a, b, c) {
    # R(q)^T (v - x): the rotation of unit quaternion (w, a, b, c) inverted
    dx = X - px[i]; dy = Y - py[i]; dz = Z - pz[i]
    w = qw[i]; a = qx[i]; b = qy[i]; c = qz[i]
    bx = (1 - 2*(b*b + c*c))*dx + 2*(a*b + w*c)*dy + 2*(a*c - w*b)*dz
    by = 2*(a*b - w*c)*dx + (1 - 2*(a*a + c*c))*dy + 2*(b*c + w*a)*dz
    bz = 2*(a*c + w*b)*dx + 2*(b*c - w*a)*dy + (1 - 2*(a*a + b*b))*dz
}
BEGIN { n = 0; nv = 0; nf = 0 }
FNR == NR {
    if (FNR > 1) {
        px[n] = $3; py[n] = $4; pz[n] = $5
        qw[n] = $6; qx[n] = $7; qy[n] = $8; qz[n] = $9
        n++
    }
    next
}
FNR == 1 { FS = " "; $0 = $0; maxRho = 0; minZ = 1e300; maxZ = -1e300 }
$1 == "vertex" {
    verts[nv] = $2 " " $3 " " $4
    nv++
}
$1 == "endfacet" { nf++ }
END {
    if (n == 0 || nf == 0 || nf % n != 0) {
        print "pellets " n; print "facets " nf; print "error 1"
        exit
    }
    per = 3*nf/n
    maxPose = 0
    for (k = 0; k < nv; k++) {
        split(verts[k], v, " ")
        rho = sqrt(v[1]*v[1] + v[2]*v[2])
        if (rho > maxRho) maxRho = rho
        if (v[3] < minZ) minZ = v[3]
        if (v[3] > maxZ) maxZ = v[3]
        i = int(k/per); j = k % per
        tobody(i, v[1], v[2], v[3])
        if (i == 0) {
            tx[j] = bx; ty[j] = by; tz[j] = bz
        } else {
            d = sqrt((bx - tx[j])^2 + (by - ty[j])^2 + (bz - tz[j])^2)
            if (d > maxPose) maxPose = d
        }
    }
    # Pellet 0 in its body frame: volume, extents, radii
    vol = 0; bodyMaxR = 0; bodyMaxAbsZ = 0; bodyMaxRhoZ = 0
    for (j = 0; j < per; j += 3) {
        ax = tx[j]; ay = ty[j]; az = tz[j]
        ux = tx[j+1]; uy = ty[j+1]; uz = tz[j+1]
        wx = tx[j+2]; wy = ty[j+2]; wz = tz[j+2]
        vol += (ax*(uy*wz - uz*wy) + ay*(uz*wx - ux*wz) + az*(ux*wy - uy*wx))/6
    }
    for (j = 0; j < per; j++) {
        r = sqrt(tx[j]^2 + ty[j]^2 + tz[j]^2)
        if (r > bodyMaxR) bodyMaxR = r
        if (tz[j] > bodyMaxAbsZ) bodyMaxAbsZ = tz[j]
        if (-tz[j] > bodyMaxAbsZ) bodyMaxAbsZ = -tz[j]
        rz = sqrt(tx[j]^2 + ty[j]^2)
        if (rz > bodyMaxRhoZ) bodyMaxRhoZ = rz
        if (radii != "") printf "%.12g\n", r | ("sort -g > " radii)
    }
    printf "pellets %d\nfacets %d\n", n, nf
    printf "maxRho %.12g\nminZ %.12g\nmaxZ %.12g\n", maxRho, minZ, maxZ
    printf "maxPoseError %.6g\nvolume %.12g\n", maxPose, vol
    printf "bodyMaxR %.12g\nbodyMaxAbsZ %.12g\nbodyMaxRhoZ %.12g\n", \
        bodyMaxR, bodyMaxAbsZ, bodyMaxRhoZ
}
