/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// main() of every unit test: GoogleTest's, except that a run in which every
// test skipped itself (no GPU, no OpenFOAM) and none failed exits 77, which
// CTest reports as skipped. A run with any failure fails, skips or not.

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    const int status = RUN_ALL_TESTS();
    const ::testing::UnitTest& run = *::testing::UnitTest::GetInstance();
    if
    (
        status == 0 && run.failed_test_count() == 0
     && run.successful_test_count() == 0 && run.skipped_test_count() > 0
    )
    {
        return 77;
    }
    return status;
}
