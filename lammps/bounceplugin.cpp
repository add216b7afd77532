/* The LAMMPS plugin of bounce: `plugin load bounceplugin.so` registers pair_style bounce and fix wall/bounce
   (docs/lammps.md). */

#include "lammpsplugin.h"
#include "version.h"

#include "fix_wall_bounce.h"
#include "pair_bounce.h"

using namespace LAMMPS_NS;

static Pair *bounce_creator(LAMMPS *lmp)
{
  return new PairBounce(lmp);
}

static Fix *wall_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixWallBounce(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  plugin.version = LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "bounce";
  plugin.info = "bounce's contact laws for colliding grains (docs/lammps.md)";
  plugin.author = "the bounce developers";
  plugin.creator.v1 = reinterpret_cast<lammpsplugin_factory1 *>(&bounce_creator);
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "wall/bounce";
  plugin.info = "flat walls with bounce's contact laws (docs/lammps.md)";
  plugin.creator.v2 = reinterpret_cast<lammpsplugin_factory2 *>(&wall_creator);
  (*register_plugin)(&plugin, lmp);
}
