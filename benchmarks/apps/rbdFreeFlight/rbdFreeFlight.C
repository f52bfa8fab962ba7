/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Application
    rbdFreeFlight

Description
    The free-flight check of benchmarks/accuracyVsTime: one pellet thrown
    with spin (v = (0.3, 0.2, 2) m/s, omega = (30, 50, 80) rad/s) in a tube
    far too wide and tall to be touched, stepped with the library's world
    for endTime; prints the relative change of the total energy
    (translational and rotational kinetic plus potential m g z) and the
    steps. Spheres spin at constant omega, so their drift is round-off;
    for other shapes the torque-free rotation tests the integrator.

Usage
    rbdFreeFlight "<pellets entries>" "<simulation entries>" [endTime]

    \verbatim
    rbdFreeFlight "shape cylinder; diameter 0.01; height 0.01; faces 200;" \
        "preset fast;" 1
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "world.H"
#include "IStringStream.H"
#include "clockTime.H"

#include <cstdlib>
#include <iostream>

using namespace Foam;
using namespace Foam::rbd;

static dictionary parse(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}


int main(int argc, char* argv[])
{
    if (argc < 3 || argc > 4)
    {
        std::cerr
            << "Usage: rbdFreeFlight \"<pellets entries>\" "
            << "\"<simulation entries>\" [endTime]" << std::endl;
        return 1;
    }
    const scalar endTime = argc == 4 ? std::atof(argv[3]) : 1.0;

    const dictionary pellets(parse(argv[1]));
    autoPtr<pelletShape> shape(pelletShape::New(pellets));
    const simulationControls controls(parse(argv[2]));
    const tube container(2, 20, 0.1, 0.9);
    const pelletMaterial material{8030, 0.1, 0.9};
    world w(container, shape(), material, true, controls);

    const label id = w.addBody(point(0, 0, 10), quaternion(1));
    w.setVelocity(id, vector(0.3, 0.2, 2), vector(30, 50, 80));

    const scalar g = controls.gravity;
    const scalar m = w.bodies()[0].mass();
    auto energy = [&]()
    {
        return w.kineticEnergy() + m*g*w.bodies()[0].x().z();
    };

    const scalar E0 = energy();
    clockTime timer;
    while (w.time() < endTime - 1e-12)
    {
        const scalar tOuter =
            controls.deltaT*(std::floor(w.time()/controls.deltaT + 1e-9) + 1);
        w.step(min(tOuter, endTime) - w.time());
    }
    const scalar E1 = energy();

    Info().precision(10);
    Info<< "shape " << shape->type() << nl
        << "deltaT " << controls.deltaT << nl
        << "time " << w.time() << nl
        << "steps " << w.stats().steps << nl
        << "energyStart " << E0 << nl
        << "energyEnd " << E1 << nl
        << "relativeEnergyChange " << (E1 - E0)/E0 << nl
        << "quaternionError " << mag(mag(w.bodies()[0].q()) - 1) << nl
        << "wallTime " << timer.elapsedTime() << endl;
    return 0;
}


// ************************************************************************* //
