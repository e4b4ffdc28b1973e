#include <pg/postprocess/postprocessor.h>
#include <pg/postprocess/postprocessors.h>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    Interface<dim>::finalize(const ProblemView<dim> &,
                             const Step &,
                             TableHandler &,
                             RunSummary &)
    {}



    template <int dim>
    Manager<dim>::Manager()
    {
      postprocessors.push_back(std::make_unique<PointValues<dim>>());
      postprocessors.push_back(std::make_unique<LineSamples<dim>>());
      postprocessors.push_back(std::make_unique<Reactions<dim>>());
      postprocessors.push_back(std::make_unique<ParticleFields<dim>>());
      postprocessors.push_back(std::make_unique<ErrorNorms<dim>>());
      postprocessors.push_back(std::make_unique<NodalStresses<dim>>());
      postprocessors.push_back(std::make_unique<Statistics<dim>>());
      auto writer   = std::make_unique<VtuOutput<dim>>();
      output_writer = writer.get();
      postprocessors.push_back(std::move(writer));
    }



    template <int dim>
    Manager<dim>::~Manager() = default;



    template <int dim>
    void
    Manager<dim>::execute(const ProblemView<dim> &view,
                          const Step             &step,
                          TableHandler           &statistics,
                          RunSummary             &summary)
    {
      for (const auto &p : postprocessors)
        p->execute(view, step, statistics, summary);
    }



    template <int dim>
    void
    Manager<dim>::finalize(const ProblemView<dim> &view,
                           const Step             &step,
                           TableHandler           &statistics,
                           RunSummary             &summary)
    {
      for (const auto &p : postprocessors)
        p->finalize(view, step, statistics, summary);
    }



    template <int dim>
    VtuOutput<dim> &
    Manager<dim>::output()
    {
      return *output_writer;
    }



    template class Interface<2>;
    template class Interface<3>;
    template class Manager<2>;
    template class Manager<3>;
  } // namespace Postprocess
} // namespace pg
