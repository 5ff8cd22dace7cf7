#pragma once
// Starts MPI for the life of a program (a thin main makes one first) and ends it. Without MPI in the
// build, or when no launcher (mpirun, srun) started the program, MPI is not started and the run is
// one rank as before.
namespace dpd {

class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

private:
    bool started_ = false;
};

}  // namespace dpd
