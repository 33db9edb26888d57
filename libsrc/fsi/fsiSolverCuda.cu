/*---------------------------------------------------------------------------*\
  sphvcpm: mesh-less fluid-structure interaction (SPH + VCPM)
\*---------------------------------------------------------------------------*/
// The GPU side of fsiSolver: the particles in device memory
// (cudaParticleStore, the device twin of hostParticleStore) and the step of
// fsiSolverSteps.H instantiated on it. The particles stay on the GPU
// between steps; they come back to the host for writes, function objects
// and diagnoses. The solids are sub-cycled on the GPU too, from their
// own device arrays (fluidSolidCouplingCuda.cu).
#include "fsiSolverSteps.H"
#include "parallelCuda.cuh"

#include <cstring>

namespace sphvcpm
{

namespace
{

// Grows a buffer to at least n elements (contents not kept).
template<class T>
T* atLeast(deviceBuffer<T>& buffer, const label n)
{
    if (buffer.size() < n) buffer.resize(n);
    return buffer.data();
}

template<class T>
void download(const deviceBuffer<T>& from, std::vector<T>& to, const label n)
{
    to.resize(n);
    if (n > 0) from.copyToHost(to.data(), n);
}

template<class T>
void upload(deviceBuffer<T>& to, const std::vector<T>& from)
{
    to.resize(label(from.size()));
    if (!from.empty()) to.copyFromHost(from);
}

} // End anonymous namespace


struct cudaParticleStore
{
    using execType = cudaExec;
    static constexpr bool pairForm = false;

    particleFields& host;
    cellList& hostCells;
    const bool withSps;
    const bool withShifting;
    const bool withLink;
    const bool withPrevious;

    // The particles: n in use; buffers are never shrunk, as particles
    // only leave.
    label n = 0;
    deviceBuffer<point> position;
    deviceBuffer<vec3> velocity, velocity0, acceleration;
    deviceBuffer<point> positionScratch;   // single builds (particleFields.H)
    deviceBuffer<scalar> rho, p, mass, rho0, drho, invRho;
    deviceBuffer<std::uint8_t> kind, body, newKind, newBody;
    deviceBuffer<label> id, link, newId, newLink;
    deviceBuffer<symmTensor> tau;
    deviceBuffer<vec3> shiftGradient;
    deviceBuffer<scalar> divR;
    deviceBuffer<vec3> velocityPrevious;   // Verlet only
    deviceBuffer<scalar> rhoPrevious;

    // The cell list and the per-step flags.
    cellGrid grid;
    label nInside = 0;
    deviceBuffer<std::uint32_t> keysOf;
    deviceBuffer<label> order, cellStartOf, kindEndOf, rowStartOf;
    deviceBuffer<std::uint32_t> blockHasFluidOf;
    deviceBuffer<std::uint8_t> nearFluidOf;
    deviceBuffer<scalar> viscTermOf;

    // The coupling, when there are solids (its arrays are on the GPU).
    fluidSolidCoupling* coupling = nullptr;

    cudaParticleStore(particleFields& h, cellList& cells, const bool sps,
                      const bool shifting)
    :
        host(h),
        hostCells(cells),
        withSps(sps),
        withShifting(shifting),
        withLink(!h.link.empty()),
        withPrevious(!h.velocityPrevious.empty()),
        n(h.size())
    {
        upload(position, host.position);
        upload(velocity, host.velocity);
        upload(rho, host.rho);
        upload(p, host.p);
        upload(mass, host.mass);
        upload(kind, host.kind);
        upload(body, host.body);
        upload(id, host.id);
        upload(link, host.link);
        for (deviceBuffer<vec3>* b : {&velocity0, &acceleration}) b->resize(n);
        for (deviceBuffer<scalar>* b : {&rho0, &drho, &invRho}) b->resize(n);
        newKind.resize(n);
        newBody.resize(n);
        newId.resize(n);
        newLink.resize(withLink ? n : 0);
        tau.resize(withSps ? n : 0);
        shiftGradient.resize(withShifting ? n : 0);
        divR.resize(withShifting ? n : 0);
        upload(velocityPrevious, host.velocityPrevious);
        upload(rhoPrevious, host.rhoPrevious);

        // The host's list matches the host's (sorted) particles.
        grid = cells.grid;
        nInside = cells.nInside;
        upload(keysOf, cells.keys);
        upload(order, cells.order);
        upload(cellStartOf, cells.cellStart);
        upload(kindEndOf, cells.kindEnd);
    }

    execType exec() const { return {}; }
    label size() const { return n; }

    particleView view()
    {
        return particleView
        {
            n,
            position.data(), velocity.data(), rho.data(), p.data(),
            mass.data(), kind.data(), body.data(), id.data(),
            velocity0.data(), rho0.data(), acceleration.data(), drho.data(),
            invRho.data(),
            withSps ? tau.data() : nullptr,
            withShifting ? shiftGradient.data() : nullptr,
            withShifting ? divR.data() : nullptr,
            withLink ? link.data() : nullptr,
            withPrevious ? velocityPrevious.data() : nullptr,
            withPrevious ? rhoPrevious.data() : nullptr
        };
    }

    label sortByCell(const cellGrid& g)
    {
        grid = g;
        label* cellStart = atLeast(cellStartOf, grid.nCells() + 1);
        label* kindEnd = atLeast(kindEndOf, 2*grid.nCells());
        if (n > 0)
        {
            parallelFor(cudaExec{}, n,
                detail::cellKeyOp{grid, position.data(), kind.data(),
                                  keysOf.data(), order.data()});
            sortByKey(cudaExec{}, keysOf.data(), order.data(), n);
        }
        fillCellRanges(cudaExec{}, grid, keysOf.data(), n,
                       atLeast(rowStartOf, grid.nRows() + 1), cellStart,
                       kindEnd, atLeast(blockHasFluidOf, grid.nBlocks()));
        copyDeviceToHost(&nInside, cellStart + grid.nCells(), sizeof(label));
        return nInside;
    }

    std::vector<outsideParticle> outside() const
    {
        // Rare (a particle left the domain): the whole arrays come over.
        std::vector<label> o;
        std::vector<std::uint8_t> k, b;
        std::vector<point> x;
        download(order, o, n);
        download(kind, k, n);
        download(body, b, n);
        download(position, x, n);
        std::vector<outsideParticle> out;
        for (label s = nInside; s < n; ++s)
        {
            const label i = o[s];
            out.push_back({i, k[i], b[i], x[i]});
        }
        return out;
    }

    void keepInside(bool, bool)
    {
        deviceBuffer<point>& newPosition =
            positionScratchOf(positionScratch, velocity0);
        point* newPositionData = atLeast(newPosition, n);
        parallelFor(cudaExec{}, nInside, reorderOp{order.data(),
            position.data(), newPositionData,
            velocity.data(), acceleration.data(),
            rho.data(), rho0.data(),
            p.data(), drho.data(),
            mass.data(), invRho.data(),
            kind.data(), newKind.data(),
            body.data(), newBody.data(),
            id.data(), newId.data(),
            withLink ? link.data() : nullptr, newLink.data()});
        std::swap(position, newPosition);
        std::swap(velocity, acceleration);
        std::swap(rho, rho0);
        std::swap(p, drho);
        std::swap(mass, invRho);
        std::swap(kind, newKind);
        std::swap(body, newBody);
        std::swap(id, newId);
        std::swap(link, newLink);
        if (withPrevious)
        {
            // Into two step fields that the first gather has just freed.
            parallelFor(cudaExec{}, nInside, reorderPreviousOp{order.data(),
                velocityPrevious.data(), acceleration.data(),
                rhoPrevious.data(), drho.data()});
            std::swap(velocityPrevious, acceleration);
            std::swap(rhoPrevious, drho);
        }
        n = nInside;
    }

    const label* cellStart() const { return cellStartOf.data(); }
    const label* kindEnd() const { return kindEndOf.data(); }
    const std::uint32_t* keys() const { return keysOf.data(); }

    const std::uint32_t* blockHasFluid() const
    {
        return blockHasFluidOf.data();
    }
    std::uint8_t* nearFluid(const label m) { return atLeast(nearFluidOf, m); }
    scalar* viscTerm(const label m) { return atLeast(viscTermOf, m); }

    // The coupling lives on the GPU too (fluidSolidCouplingCuda.cu): its
    // force and state arrays are device memory.
    void solidForce(fluidSolidCoupling& c)
    {
        parallelFor(cudaExec{}, n, fluidForceOnSolidOp{view(),
            c.deviceFluidForce()});
    }

    contactPlane* contactPlanes(fluidSolidCoupling& c)
    {
        return c.deviceContact();
    }

    void putSolids(const fluidSolidCoupling& c)
    {
        parallelFor(cudaExec{}, n, solidToParticlesOp{view(),
            c.devicePosition(), c.deviceMeanVelocity()});
    }

    // The moving walls' moves by body: a few hundred bytes, copied on the
    // default stream after the kernels that read the last ones, and only
    // when they changed (the wall pass after a move reads the same ones; a
    // copy from the host waits for the GPU).
    deviceBuffer<bodyMove> moves;
    std::vector<bodyMove> movesOnDevice;
    const bodyMove* bodyMoves(const std::vector<bodyMove>& m)
    {
        if (m.size() != movesOnDevice.size() || std::memcmp(m.data(),
                movesOnDevice.data(), m.size()*sizeof(bodyMove)) != 0)
        {
            upload(moves, m);
            movesOnDevice = m;
        }
        return moves.data();
    }

    // The particles, the cell list and the solids into the host's arrays.
    void toHost()
    {
        if (coupling) coupling->toHost();
        host.resize(n, withSps, withShifting, withPrevious);
        download(position, host.position, n);
        download(velocity, host.velocity, n);
        download(rho, host.rho, n);
        download(p, host.p, n);
        download(mass, host.mass, n);
        download(kind, host.kind, n);
        download(body, host.body, n);
        download(id, host.id, n);
        download(link, host.link, withLink ? n : 0);
        download(velocity0, host.velocity0, n);
        download(acceleration, host.acceleration, n);
        download(rho0, host.rho0, n);
        download(drho, host.drho, n);
        download(invRho, host.invRho, n);
        download(tau, host.tau, withSps ? n : 0);
        download(shiftGradient, host.shiftGradient, withShifting ? n : 0);
        download(divR, host.divR, withShifting ? n : 0);
        download(velocityPrevious, host.velocityPrevious,
                 withPrevious ? n : 0);
        download(rhoPrevious, host.rhoPrevious, withPrevious ? n : 0);
        hostCells.grid = grid;
        hostCells.nInside = nInside;
        download(keysOf, hostCells.keys, n);
        download(order, hostCells.order, n);
        download(cellStartOf, hostCells.cellStart, grid.nCells() + 1);
        download(kindEndOf, hostCells.kindEnd, 2*grid.nCells());
    }
};


void cudaParticleStoreDeleter::operator()(cudaParticleStore* store) const
{
    delete store;
}


void fsiSolver::startGpu()
{
    gpu_.reset(new cudaParticleStore(particles_, cells_, model_.sps,
        model_.shifting != shiftingType::none));
    if (coupling_)
    {
        coupling_->useDevice();
        gpu_->coupling = coupling_.get();
    }
}


void fsiSolver::stepGpu()
{
    stepOn(*gpu_);
}


void fsiSolver::gpuToHost()
{
    gpu_->toHost();
}


void fsiSolver::updateWallsGpu()
{
    updateWallsOn(*gpu_, false);
}


double fsiSolver::countInteractionsGpu()
{
    return countInteractionsOn(*gpu_);
}

} // End namespace sphvcpm
