#pragma once
// A T-posed humanoid skeleton as .iv text (SkeletonJoints), for tests of Mannequin
// scenes: y up, facing +z, left = +x, arms along x at 1.42 m (shoulders at +-0.2 m,
// elbows +-0.45, wrists +-0.7), hips at 0.9 m.

namespace figment::test {

inline constexpr const char* kTPoseJoints =
    "SkeletonJoints {\n"
    "  names [ \"pelvis\", \"waist\", \"chest\", \"neckBase\", \"neckTop\", \"headTop\",\n"
    "          \"hipL\", \"kneeL\", \"ankleL\", \"toeL\", \"hipR\", \"kneeR\", \"ankleR\", \"toeR\",\n"
    "          \"shoulderBaseL\", \"shoulderL\", \"elbowL\", \"wristL\", \"fingertipL\",\n"
    "          \"shoulderBaseR\", \"shoulderR\", \"elbowR\", \"wristR\", \"fingertipR\", \"pelvisFloor\" ]\n"
    "  positions [ 0 0.9 0, 0 1.05 0, 0 1.25 0, 0 1.45 0, 0 1.55 0, 0 1.75 0,\n"
    "              0.1 0.9 0, 0.1 0.5 0, 0.1 0.08 0, 0.1 0.02 0.15,\n"
    "              -0.1 0.9 0, -0.1 0.5 0, -0.1 0.08 0, -0.1 0.02 0.15,\n"
    "              0.05 1.42 0, 0.2 1.42 0, 0.45 1.42 0, 0.7 1.42 0, 0.88 1.42 0,\n"
    "              -0.05 1.42 0, -0.2 1.42 0, -0.45 1.42 0, -0.7 1.42 0, -0.88 1.42 0,\n"
    "              0 0.8 0 ]\n"
    "}\n";

// The left forearm's capsule: along +x (the unit capsule's y turned by -90 degrees
// about z), 8 cm thick, from 0.4 to 0.75 m.
inline constexpr const char* kForearmCapsule =
    "DEF Forearm CapsuleVolume { part \"forearmL\"  x 0.08 y 0.35 z 0.08  ox 0.575 oy 1.42 oz 0\n"
    "  theta -1.5707963  phi 1.5707963 }\n";

}  // namespace figment::test
