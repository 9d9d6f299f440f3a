#!/usr/bin/env python3
# Writes the hand-made inputs of tests/data/fuzz_regressions/ (see README.md there): small MRPT
# serialized files, each valid up to one length field that claims far more data than follows.
# Before the layout checks, each made MRPT allocate gigabytes (or crash) while reading it.
#   python3 tests/data/fuzz_regressions/make_crafted.py
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def obj(name, version, body):
    """An object as CArchive::WriteObject() writes it: 0x80 | name length, name, version,
    data, end flag 0x88."""
    n = name.encode()
    return bytes([0x80 | len(n)]) + n + bytes([version]) + body + b"\x88"


def f32(*v):
    return struct.pack("<%df" % len(v), *v)


def f64(*v):
    return struct.pack("<%dd" % len(v), *v)


def u32(v):
    return struct.pack("<I", v)


def i32(v):
    return struct.pack("<i", v)


def pose3d():
    return obj("mrpt::poses::CPose3D", 3, f64(0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1))


def pose2d(x=0.0):
    return obj("mrpt::poses::CPose2D", 1, f64(x, 0, 0))


def scan(rays=3, label=b"", label_len=None, tail=True):
    """CObservation2DRangeScan version 7; `label_len` overrides the stored label length."""
    body = f32(3.14159) + b"\x01" + f32(80.0) + pose3d() + u32(rays)
    if rays < 1000:
        body += f32(*[1.0] * rays) + b"\x01" * rays
    if rays >= 1000 or not tail:
        return obj("mrpt::obs::CObservation2DRangeScan", 7, body)[:-1]  # the data ends here
    body += f32(0.01) + struct.pack("<Q", 0) + f32(0.0)
    body += u32(len(label) if label_len is None else label_len) + label
    if label_len is not None:
        return obj("mrpt::obs::CObservation2DRangeScan", 7, body)[:-1]
    body += f32(0.0) + b"\x00"
    return obj("mrpt::obs::CObservation2DRangeScan", 7, body)


def odometry(label_len=None):
    body = pose2d() + u32(0 if label_len is None else label_len)
    if label_len is not None:
        return obj("mrpt::obs::CObservationOdometry", 2, body)[:-1]
    body += struct.pack("<Q", 0) + b"\x00\x00"
    return obj("mrpt::obs::CObservationOdometry", 2, body)


def movement(model=0, particles=300):
    """CActionRobotMovement2D version 7, odometry-based: the motion model is stored, the PDF
    is rebuilt by MRPT when reading (a Thrun model draws `particles` samples)."""
    body = i32(0) + pose2d(0.1) + i32(model) + f32(0.01, 0.05, 0.017, 0.05, 0.01, 0.0035)
    body += u32(particles) + f32(0.05, 0.07, 0.01, 0.0017) + f32(0.001, 0.0017)
    body += b"\x00" + b"\x00" + struct.pack("<Q", 0)
    return obj("mrpt::obs::CActionRobotMovement2D", 7, body)


def write(target, name, data):
    path = os.path.join(HERE, target, name)
    with open(path, "wb") as f:
        f.write(data)
    print("%s: %d bytes" % (os.path.relpath(path, HERE), len(data)))


def grid(owa_count=2):
    """A 4 x 3 COccupancyGridMap2D, version 6, as MRPT 2.5.8 writes it; `owa_count` overrides
    the stored length of likelihoodOptions.OWA_weights."""
    body = b"\x08" + u32(4) + u32(3) + f32(0.0, 0.4, 0.0, 0.3, 0.1) + b"\x00" * 12
    body += f32(0.0) + b"\x00" + f32(15.0, 0.65) + b"\x01" + struct.pack("<H", 1) + f32(0.001)
    body += i32(4) + f32(0.35, 0.95, 0.05, 81.0) + u32(5) + f32(0.3) + b"\x00" + f32(2.5)
    body += u32(10) + f32(1.5) + b"\x01" + i32(10) + f32(1.0) + i32(1) + f32(5.0)
    body += u32(owa_count) + f32(1.0, 2.0)
    if owa_count != 2:
        return obj("mrpt::maps::COccupancyGridMap2D", 6, body)[:-1]
    body += b"\x01" + obj("mrpt::maps::TMapGenericParams", 0, b"\x01\x01\x01")
    body += f32(1.0, 3.0) + b"\x00"
    return obj("mrpt::maps::COccupancyGridMap2D", 6, body)


def main():
    r = "fuzz_rawlog"
    # std::string of 4 GB for the sensor label of a scan, then of an odometry reading.
    write(r, "crafted_scan_label_4gb.rawlog", scan(label_len=0xFFFFFF00))
    write(r, "crafted_odometry_label_4gb.rawlog", odometry() + odometry(label_len=0xFFFFFFF0))
    # 2^31 - 1 rays: ranges, flags and intensities (18 GB) through MRPT's aligned allocator.
    write(r, "crafted_scan_rays_2g.rawlog", scan(rays=0x7FFFFFFF))
    # A sensory frame of 2^31 - 1 observations: a deque of shared pointers (32 GB).
    write(r, "crafted_frame_observation_count.rawlog",
          obj("mrpt::obs::CSensoryFrame", 2, u32(0x7FFFFFFF) + scan())[:-1])
    # An action collection of 2^32 - 1 actions: a vector of shared pointers (64 GB).
    write(r, "crafted_action_count.rawlog",
          obj("mrpt::obs::CActionCollection", 0, u32(0xFFFFFFFF) + movement())[:-1])
    # A valid odometry action whose Thrun motion model asks for 2^31 - 1 particles: MRPT
    # draws them while reading, with no data behind the count.
    write(r, "crafted_thrun_particles.rawlog",
          obj("mrpt::obs::CActionCollection", 0, u32(1) + movement(1, 0x7FFFFFFF)))
    # A scan of version 4 whose covSensorPose matrix declares 65536 x 65536 floats (16 GB).
    body = f32(3.14) + b"\x01" + f32(80.0) + pose3d()
    body += obj("mrpt::math::CMatrixF", 0, u32(65536) + u32(65536))[:-1]
    write(r, "crafted_scan_matrix_16gb.rawlog",
          obj("mrpt::obs::CObservation2DRangeScan", 4, body)[:-1])

    g = "fuzz_gridmap"
    # likelihoodOptions.OWA_weights declares 2^30 floats (4 GB).
    write(g, "crafted_owa_weights_4gb.gridmap", grid(owa_count=0x40000000))


if __name__ == "__main__":
    main()
