// The plugin loads into a PLUGIN-enabled LAMMPS of this version with "plugin load".
// Run without LAMMPS_PLUGIN_PATH so that nothing is autoloaded.

#include "info.h"
#include "input.h"
#include "lammps.h"

#include "../testing/core.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;

bool verbose = false;

#ifndef ESPH_PLUGIN_FILE
#error "ESPH_PLUGIN_FILE must be defined"
#endif

class PluginTest : public LAMMPSTest {};

TEST_F(PluginTest, LoadAndList)
{
  ASSERT_FALSE(info->has_style("pair", "esph/solid"))
      << "esph/solid is already there: unset LAMMPS_PLUGIN_PATH for this test";
  auto out = CAPTURE_OUTPUT([&] {
    command("plugin load " ESPH_PLUGIN_FILE);
  });
  EXPECT_THAT(out, ContainsRegex(".*Loading plugin: ESPH elastic solid SPH pair style.*"));
  EXPECT_THAT(out, ContainsRegex(".*Loading plugin: ESPH time integration.*"));
  EXPECT_THAT(out, ContainsRegex(".*Loading plugin: ESPH non-mass boundary particles.*"));
  EXPECT_TRUE(info->has_style("pair", "esph/solid"));
  EXPECT_TRUE(info->has_style("fix", "esph/integrate"));
  EXPECT_TRUE(info->has_style("fix", "esph/boundary"));
  out = CAPTURE_OUTPUT([&] {
    command("plugin list");
  });
  EXPECT_THAT(out, ContainsRegex(".*pair style plugin esph/solid.*"));
  // a second load of the same styles is ignored
  out = CAPTURE_OUTPUT([&] {
    command("plugin load " ESPH_PLUGIN_FILE);
  });
  EXPECT_THAT(out,
              ContainsRegex(".*Ignoring load of pair style esph/solid: must unload existing "
                            "esph/solid plugin first.*"));
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleMock(&argc, argv);
  if ((argc > 1) && (strcmp(argv[1], "-v") == 0)) verbose = true;
  int rv = RUN_ALL_TESTS();
  MPI_Finalize();
  return rv;
}
