// bulletPack: packs a placed column of pellets in a tube with Bullet, as
// Blender users run it (benchmarks/peerSpeed builds and runs it).
//
//   g++ -O2 -o bulletPack bulletPack.cpp $(pkg-config --cflags --libs bullet)
//   bulletPack key=value ...   (every setting is printed at the start)
//
// Units inside Bullet: lengths in pellet diameters (d = 1 unit: Debian's
// Bullet is single precision), time in s, mass in kg, so gravity is
// g/d units/s^2. Input and output in SI: the placement and the final poses
// are CSV files 'id,shape,x,y,z,qw,qx,qy,qz' [m] (rbdPackBed's pellets.csv).
//
// Settle test (the same as rbdPackBed's and the LIGGGHTS input's): the
// kinetic energy (translation + rotation, SI) at most settleEnergy n m g d
// for settleTime s without a break, checked once per frame.

#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{

std::map<std::string, std::string> settings;

std::string get(const std::string& key, const std::string& dflt)
{
    auto it = settings.find(key);
    const std::string v = it == settings.end() ? dflt : it->second;
    settings[key] = v;
    return v;
}

double num(const std::string& key, double dflt)
{
    std::ostringstream os;
    os.precision(10);
    os << dflt;
    return std::atof(get(key, os.str()).c_str());
}

struct Pose
{
    int id;
    double x, y, z, qw, qx, qy, qz;
};

std::vector<Pose> readPlacement(const std::string& path)
{
    std::ifstream in(path);
    if (!in)
    {
        std::cerr << "bulletPack: cannot read " << path << '\n';
        std::exit(2);
    }
    std::vector<Pose> out;
    std::string line;
    std::getline(in, line);     // header
    while (std::getline(in, line))
    {
        if (line.empty()) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string item;
        while (std::getline(ss, item, ',')) f.push_back(item);
        if (f.size() < 9) continue;
        Pose p;
        p.id = std::atoi(f[0].c_str());
        p.x = std::atof(f[2].c_str());
        p.y = std::atof(f[3].c_str());
        p.z = std::atof(f[4].c_str());
        p.qw = std::atof(f[5].c_str());
        p.qx = std::atof(f[6].c_str());
        p.qy = std::atof(f[7].c_str());
        p.qz = std::atof(f[8].c_str());
        out.push_back(p);
    }
    return out;
}

long long steps = 0;

void countStep(btDynamicsWorld*, btScalar)
{
    ++steps;
}

} // namespace


int main(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        const auto eq = a.find('=');
        if (eq == std::string::npos)
        {
            std::cerr << "bulletPack: arguments are key=value, not " << a
                      << '\n';
            return 2;
        }
        settings[a.substr(0, eq)] = a.substr(eq + 1);
    }

    // Geometry [m], materials, tube
    const std::string shape = get("shape", "sphere");
    const double d = num("diameter", 0.01);            // outer diameter
    const double h = num("height", d);                 // cylinder, ring, trilobe
    const double di = num("innerDiameter", 0.6*d);     // ring
    const double dl = num("lobeDiameter", 0.6*d);      // trilobe
    const double dc = num("lobePitchDiameter", 0.4*d); // trilobe
    const int ringPieces = int(num("ringPieces", 16));
    const int arcPoints = int(num("arcPointsPerPiece", 4));
    const double mass = num("mass", 0);                // [kg]
    const double Ixx = num("Ixx", 0);                  // [kg m^2], = Iyy
    const double Izz = num("Izz", 0);                  // [kg m^2]
    const double tubeD = num("tubeDiameter", 0.05);
    const double tubeH = num("tubeHeight", 1.0);
    const int wallPieces = int(num("wallPieces", 72));
    const double mu = num("friction", 0.5);
    const double e = num("restitution", 0.5);
    const double muW = num("wallFriction", mu);
    const double eW = num("wallRestitution", e);
    // Bullet multiplies the two bodies' coefficients: each body gets the
    // square root of the pair's value (wall: the pair value / pellet's)
    const double g = num("gravity", 9.81);

    // Blender's settings
    const double hz = num("hz", 2400);
    const double fps = num("fps", 24);
    const int iterations = int(num("solverIterations", 10));
    const double marginD = num("margin", 0.04);        // per d
    const double linDamp = num("linearDamping", 0.04); // Blender default
    const double angDamp = num("angularDamping", 0.1); // Blender default
    const bool splitImpulse = num("splitImpulse", 0) != 0; // Blender: off
    const bool deactivation = num("deactivation", 0) != 0; // Blender: off
    // Bullet applies restitution to contacts approaching faster than this
    // [m/s]; default: Bullet's own 0.2 units/s, as Blender leaves it
    const double restThreshold = num("restitutionThreshold", 0.2*d); // [m/s]

    // Run control
    const double settleEnergy = num("settleEnergy", 1e-6);
    const double settleTime = num("settleTime", 0.5);
    const double endTime = num("endTime", 60);
    const double wallLimit = num("wallLimit", 1e9);
    const double logInterval = num("logInterval", 0.5);
    const std::string placement = get("placement", "placement.csv");
    const std::string output = get("output", "bullet.csv");

    const int substeps = int(std::lround(hz/fps));
    std::cout << "bulletPack: Bullet " << btGetVersion()
              << (sizeof(btScalar) == 4 ? " single" : " double")
              << " precision\nsettings:\n";
    for (const auto& kv : settings)
    {
        std::cout << "  " << kv.first << " = " << kv.second << '\n';
    }
    std::cout << "  substeps per frame = " << substeps
              << "\n  length unit = d = " << d << " m, gravity = " << g/d
              << " units/s^2\n  body friction = sqrt(friction) = "
              << std::sqrt(mu) << ", body restitution = sqrt(restitution) = "
              << std::sqrt(e) << " (Bullet multiplies the pair's values)\n";
    if (mass <= 0 || Ixx <= 0 || Izz <= 0)
    {
        std::cerr << "bulletPack: give mass, Ixx and Izz\n";
        return 2;
    }

    const double L = d;                 // length unit [m]
    const btScalar margin = btScalar(marginD);   // in units of d

    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, 0, btScalar(-g/L)));
    world.getSolverInfo().m_numIterations = iterations;
    world.getSolverInfo().m_splitImpulse = splitImpulse;
    world.getSolverInfo().m_restitutionVelocityThreshold =
        btScalar(restThreshold/d);
    world.setInternalTickCallback(countStep);

    std::vector<std::unique_ptr<btCollisionShape>> shapes;

    // Tube: a floor plane and wallPieces boxes whose inner faces touch the
    // circle of the tube's radius
    const btScalar R = btScalar(0.5*tubeD/L);
    const btScalar H = btScalar(tubeH/L);
    const btScalar t = btScalar(num("wallThickness", 5));  // units: no tunnelling
    {
        auto floor = std::make_unique<btStaticPlaneShape>
        (
            btVector3(0, 0, 1), 0
        );
        floor->setMargin(margin);
        auto tube = std::make_unique<btCompoundShape>();
        const btScalar halfW = (R + t)*std::tan(SIMD_PI/wallPieces)*1.05f;
        auto box = std::make_unique<btBoxShape>
        (
            btVector3(t/2, halfW, H/2 + 1)
        );
        box->setMargin(margin);
        for (int k = 0; k < wallPieces; ++k)
        {
            const btScalar phi = 2*SIMD_PI*k/wallPieces;
            btTransform tr;
            tr.setIdentity();
            tr.setRotation(btQuaternion(btVector3(0, 0, 1), phi));
            tr.setOrigin
            (
                btVector3((R + t/2)*std::cos(phi), (R + t/2)*std::sin(phi),
                          H/2)
            );
            tube->addChildShape(tr, box.get());
        }
        for (btCollisionShape* s : {static_cast<btCollisionShape*>(floor.get()),
                                    static_cast<btCollisionShape*>(tube.get())})
        {
            btTransform tr;
            tr.setIdentity();
            btRigidBody::btRigidBodyConstructionInfo ci(0, nullptr, s);
            auto* body = new btRigidBody(ci);
            body->setWorldTransform(tr);
            body->setFriction(btScalar(muW/std::sqrt(mu)));
            body->setRestitution(btScalar(eW/std::sqrt(e)));
            world.addRigidBody(body);
        }
        shapes.push_back(std::move(floor));
        shapes.push_back(std::move(box));
        shapes.push_back(std::move(tube));
    }

    // The pellet's shape, centred, axis z
    btCollisionShape* pellet = nullptr;
    if (shape == "sphere")
    {
        shapes.push_back(std::make_unique<btSphereShape>(0.5f));
        pellet = shapes.back().get();
    }
    else if (shape == "cylinder")
    {
        auto s = std::make_unique<btCylinderShapeZ>
        (
            btVector3(0.5f, 0.5f, btScalar(0.5*h/L))
        );
        s->setMargin(margin);
        pellet = s.get();
        shapes.push_back(std::move(s));
    }
    else if (shape == "trilobe")
    {
        auto lobe = std::make_unique<btCylinderShapeZ>
        (
            btVector3(btScalar(0.5*dl/L), btScalar(0.5*dl/L),
                      btScalar(0.5*h/L))
        );
        lobe->setMargin(margin);
        auto c = std::make_unique<btCompoundShape>();
        for (int k = 0; k < 3; ++k)
        {
            const double phi = 2*M_PI*k/3;
            btTransform tr;
            tr.setIdentity();
            tr.setOrigin
            (
                btVector3(btScalar(0.5*dc/L*std::cos(phi)),
                          btScalar(0.5*dc/L*std::sin(phi)), 0)
            );
            c->addChildShape(tr, lobe.get());
        }
        pellet = c.get();
        shapes.push_back(std::move(lobe));
        shapes.push_back(std::move(c));
    }
    else if (shape == "ring")
    {
        // ringPieces annular sectors, each the convex hull of arcPoints + 1
        // points on the outer arc and the 2 ends of the inner chord, top
        // and bottom, inset by the margin that Bullet adds around a hull
        auto c = std::make_unique<btCompoundShape>();
        const double ro = 0.5*d/L - marginD, ri = 0.5*di/L + marginD;
        const double hz2 = 0.5*h/L - marginD;
        for (int k = 0; k < ringPieces; ++k)
        {
            auto hull = std::make_unique<btConvexHullShape>();
            const double p0 = 2*M_PI*k/ringPieces;
            const double p1 = 2*M_PI*(k + 1)/ringPieces;
            for (double z : {-hz2, hz2})
            {
                for (int j = 0; j <= arcPoints; ++j)
                {
                    const double p = p0 + (p1 - p0)*j/arcPoints;
                    hull->addPoint(btVector3(btScalar(ro*std::cos(p)),
                                             btScalar(ro*std::sin(p)),
                                             btScalar(z)), false);
                }
                for (double p : {p0, p1})
                {
                    hull->addPoint(btVector3(btScalar(ri*std::cos(p)),
                                             btScalar(ri*std::sin(p)),
                                             btScalar(z)), false);
                }
            }
            hull->recalcLocalAabb();
            hull->setMargin(margin);
            btTransform tr;
            tr.setIdentity();
            c->addChildShape(tr, hull.get());
            shapes.push_back(std::move(hull));
        }
        pellet = c.get();
        shapes.push_back(std::move(c));
    }
    else
    {
        std::cerr << "bulletPack: unknown shape " << shape << '\n';
        return 2;
    }

    const btVector3 inertia
    (
        btScalar(Ixx/(L*L)), btScalar(Ixx/(L*L)), btScalar(Izz/(L*L))
    );
    const std::vector<Pose> placed = readPlacement(placement);
    std::vector<btRigidBody*> bodies;
    for (const Pose& p : placed)
    {
        btRigidBody::btRigidBodyConstructionInfo ci
        (
            btScalar(mass), nullptr, pellet, inertia
        );
        ci.m_friction = btScalar(std::sqrt(mu));
        ci.m_restitution = btScalar(std::sqrt(e));
        ci.m_linearDamping = btScalar(linDamp);
        ci.m_angularDamping = btScalar(angDamp);
        auto* body = new btRigidBody(ci);
        btTransform tr;
        tr.setIdentity();
        tr.setOrigin(btVector3(btScalar(p.x/L), btScalar(p.y/L),
                               btScalar(p.z/L)));
        tr.setRotation(btQuaternion(btScalar(p.qx), btScalar(p.qy),
                                    btScalar(p.qz), btScalar(p.qw)));
        body->setWorldTransform(tr);
        if (!deactivation)
        {
            body->setActivationState(DISABLE_DEACTIVATION);
        }
        world.addRigidBody(body);
        bodies.push_back(body);
    }
    const double n = bodies.size();
    const double Eref = settleEnergy*n*mass*g*d;
    std::cout << "pellets = " << bodies.size() << ", settle test: KE <= "
              << Eref << " J (" << settleEnergy << " n m g d) for "
              << settleTime << " s, checked every frame" << std::endl;

    auto kinetic = [&](double& vmax)
    {
        double KE = 0;
        vmax = 0;
        for (const btRigidBody* b : bodies)
        {
            const btVector3 v = b->getLinearVelocity()*btScalar(L);
            const btVector3 w = b->getAngularVelocity();
            // body-frame angular velocity for the principal inertia
            const btVector3 wb =
                b->getWorldTransform().getBasis().transpose()*w;
            KE += 0.5*mass*v.length2()
                + 0.5*(Ixx*(wb.x()*wb.x() + wb.y()*wb.y())
                     + Izz*wb.z()*wb.z());
            vmax = std::max(vmax, double(v.length()));
        }
        return KE;
    };

    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&]()
    {
        return std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - start
        ).count();
    };

    const double frame = 1/fps, fixedStep = 1/hz;
    long long frames = 0;
    double quiet = 0, nextLog = logInterval, KE = 0, vmax = 0;
    std::string status = "notSettled";
    while (true)
    {
        world.stepSimulation(btScalar(frame), substeps + 1,
                             btScalar(fixedStep));
        ++frames;
        const double time = frames*frame;
        KE = kinetic(vmax);
        quiet = KE <= Eref ? quiet + frame : 0;
        const bool settled = quiet >= settleTime - 1e-9;
        if (time >= nextLog - 1e-9 || settled)
        {
            std::printf("Time = %.4f s  steps %lld  KE = %.4g J  vmax = "
                        "%.4g m/s  ExecutionTime = %.2f s\n", time, steps,
                        KE, vmax, elapsed());
            std::fflush(stdout);
            nextLog += logInterval;
        }
        if (settled)
        {
            status = "settled";
            break;
        }
        if (time >= endTime - 1e-9)
        {
            status = "notSettled";
            break;
        }
        if (elapsed() >= wallLimit)
        {
            status = "timeLimit";
            break;
        }
    }
    const double wall = elapsed();

    std::ofstream out(output);
    out.precision(10);
    out << "id,shape,x,y,z,qw,qx,qy,qz\n";
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        const btTransform& tr = bodies[i]->getWorldTransform();
        const btVector3 o = tr.getOrigin()*btScalar(L);
        const btQuaternion q = tr.getRotation();
        out << placed[i].id << ',' << shape << ',' << o.x() << ',' << o.y()
            << ',' << o.z() << ',' << q.w() << ',' << q.x() << ',' << q.y()
            << ',' << q.z() << '\n';
    }
    std::printf("RESULT status %s simulatedTime %.6g steps %lld "
                "wallTime %.4f kineticEnergy %.6g maxSpeed %.6g\n",
                status.c_str(), frames*frame, steps, wall, KE, vmax);
    return 0;
}
